// A timing-only build (CANOPY_TIMING_ONLY) refuses, before anything is read, the options that
// would need the image-file libraries or Embree, and says which flags to add.
#include "timing_only/timing_only.hpp"

#include <doctest/doctest.h>

using namespace canopy;

TEST_CASE("a full build refuses nothing") {
    CHECK_FALSE(timing_only_refusal(false, true, true));
    CHECK_FALSE(timing_only_refusal(false, false, false));
}

TEST_CASE("a timing-only build refuses references and image files, naming the flags to add") {
    CHECK_FALSE(timing_only_refusal(true, false, false));

    const auto reference = timing_only_refusal(true, true, false);
    REQUIRE(reference);
    CHECK(reference->find("add --no-reference,") != std::string::npos);
    CHECK(reference->find("--images none") == std::string::npos);

    const auto images = timing_only_refusal(true, false, true);
    REQUIRE(images);
    CHECK(images->find("add --images none,") != std::string::npos);
    CHECK(images->find("--no-reference") == std::string::npos);

    const auto both = timing_only_refusal(true, true, true);
    REQUIRE(both);
    CHECK(both->find("add --no-reference --images none,") != std::string::npos);
    CHECK(both->find("CANOPY_TIMING_ONLY") != std::string::npos);
}

TEST_CASE("this build knows whether it is timing-only") {
#ifdef CANOPY_TIMING_ONLY
    CHECK(kTimingOnlyBuild);
#else
    CHECK_FALSE(kTimingOnlyBuild);
#endif
}
