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

// Row-major, width x height; nullopt where the ray sees the background.
std::vector<std::optional<ReferenceHit>> reference_hits(const Scene& scene, const EmbreeScene& embree, uint32_t width,
                                                        uint32_t height);

}  // namespace canopy::test
