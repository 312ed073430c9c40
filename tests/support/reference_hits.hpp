// The Embree reference's primary hit at every pixel centre, for tests that compare what a
// technique draws with what the reference's camera rays see.
#pragma once

#include "reference/embree_scene.hpp"
#include "reference/primary_hit.hpp"
#include "scene/scene.hpp"

#include <cstdint>
#include <optional>
#include <vector>

namespace canopy::test {

struct ReferenceHit {
    PrimaryHit hit;
    EmbreeInstance what;  // the object instance or population the ray hit
};

// A ray straight down from (x, from_y, z), `length` long, through the visible scene (every field
// of the ray defined); hit.geomID is RTC_INVALID_GEOMETRY_ID when it meets nothing.
RTCRayHit trace_down(const EmbreeScene& embree, float x, float z, float from_y, float length);

// Row-major, width x height; nullopt where the ray sees the background.
std::vector<std::optional<ReferenceHit>> reference_hits(const Scene& scene, const EmbreeScene& embree, uint32_t width,
                                                        uint32_t height);

}  // namespace canopy::test
