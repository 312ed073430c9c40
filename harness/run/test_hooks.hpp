// TEST-ONLY hooks that stop a run at a fixed point, so tests can kill a real run and resume it.
// They read environment variables that nothing else uses; unset, they do nothing:
//   CANOPY_TEST_KILL_AFTER_GROUPS=N  after the N-th group this process measures is recorded (its
//                                    cases' images and results.json written), the process sends
//                                    itself CANOPY_TEST_KILL_SIGNAL: KILL (default), TERM or INT;
//   CANOPY_TEST_KILL_MID_GROUP=1     instead, send it once the first case of the (N+1)-th group
//                                    has its images written, before results.json records that
//                                    group (a half-written group);
//   CANOPY_TEST_KILL_AFTER_CHUNKS=N  after the N-th chunk this process measures is recorded in
//                                    results.json (a group cut short between its chunks).
#pragma once

#include <cstddef>

namespace canopy::test_hooks {

// `groups_recorded` counts the groups this process has measured and recorded so far.
void case_images_written(size_t groups_recorded);
void group_recorded(size_t groups_recorded);
// `chunks_recorded` counts the chunks this process has measured and recorded so far.
void chunk_recorded(size_t chunks_recorded);

}  // namespace canopy::test_hooks
