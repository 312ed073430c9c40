// TEST-ONLY hooks that stop a run at a fixed point, so tests can kill a real run and resume it.
// They read environment variables that nothing else uses; unset, they do nothing:
//   CANOPY_TEST_KILL_AFTER_CASES=N  after the N-th case this process measures is recorded (its
//                                   images and results.json written), the process sends itself
//                                   CANOPY_TEST_KILL_SIGNAL: KILL (default), TERM or INT;
//   CANOPY_TEST_KILL_MID_CASE=1     instead, send it after the (N+1)-th case's images are written
//                                   but before results.json records that case (a half-written case).
#pragma once

#include <cstddef>

namespace canopy::test_hooks {

// `measured` counts the cases this process has measured so far, this one included.
void case_images_written(size_t measured);
void case_recorded(size_t measured);

}  // namespace canopy::test_hooks
