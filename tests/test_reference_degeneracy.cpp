// A reference every technique matches is flagged: a uniform image, no lit pixel, no penumbra under
// an area light; an ordinary one is not.
#include "metrics/reference_degeneracy.hpp"

#include <doctest/doctest.h>

using namespace canopy;

namespace {

// A w x h reference: radiance `value` everywhere, visibility R = `fraction`, G = `facing`.
struct Reference {
    Image radiance, visibility;
    Reference(int w, int h, float value, float fraction, float facing) : radiance(w, h), visibility(w, h) {
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                radiance.set_opaque(x, y, {value, value, value});
                visibility.set_opaque(x, y, {fraction, facing, 0.0f});
            }
    }
};

constexpr ReferenceLighting kArea{true, true}, kSun{true, false}, kNoShadowLight{false, false};

}  // namespace

TEST_CASE("a reference every technique matches is flagged, an ordinary one is not") {
    // An ordinary area-lit view: lit, shadowed and partly shadowed pixels, shading that varies.
    Reference ok(8, 4, 0.5f, 1.0f, 1.0f);
    ok.radiance.at(1, 1)[0] = 0.1f;
    ok.visibility.at(2, 2)[0] = 0.0f;  // umbra
    ok.visibility.at(3, 2)[0] = 0.4f;  // penumbra
    CHECK(degenerate_reference(ok.radiance, ok.visibility, kArea).empty());
    CHECK(degenerate_reference_text({}).empty());

    // A camera inside a closed sphere: the light reaches nothing it sees, one colour everywhere.
    const Reference inside(8, 4, 0.015f, 0.0f, 1.0f);
    CHECK(degenerate_reference(inside.radiance, inside.visibility, kArea) ==
          std::vector<std::string>{"uniform image", "no lit pixels"});
    CHECK(degenerate_reference_text({"uniform image", "no lit pixels"}) ==
          "degenerate reference: uniform image, no lit pixels");

    // An area light whose shadows fall outside the view: lit, but no pixel partly shadowed.
    Reference no_penumbra = ok;
    no_penumbra.visibility.at(3, 2)[0] = 1.0f;
    CHECK(degenerate_reference(no_penumbra.radiance, no_penumbra.visibility, kArea) ==
          std::vector<std::string>{"no penumbra"});
    // A sun casts no penumbra: nothing to flag. Nor is a partial fraction at a silhouette (G = 0).
    CHECK(degenerate_reference(no_penumbra.radiance, no_penumbra.visibility, kSun).empty());
    no_penumbra.visibility.at(4, 3)[0] = 0.5f;
    no_penumbra.visibility.at(4, 3)[1] = 0.0f;
    CHECK(degenerate_reference(no_penumbra.radiance, no_penumbra.visibility, kArea) ==
          std::vector<std::string>{"no penumbra"});

    // Without a shadow-casting light the visibility image means nothing: only the image is judged.
    CHECK(degenerate_reference(inside.radiance, inside.visibility, kNoShadowLight) ==
          std::vector<std::string>{"uniform image"});
    CHECK(degenerate_reference(ok.radiance, inside.visibility, kNoShadowLight).empty());

    // Numbers at the extremes: uniform is judged to the image's own scale, so a bright uniform
    // image is uniform and a step of 1e-3 of it is not.
    const Reference bright(4, 4, 1e6f, 1.0f, 1.0f);
    CHECK(degenerate_reference(bright.radiance, bright.visibility, kSun) == std::vector<std::string>{"uniform image"});
    Reference tiny_step(4, 4, 1e6f, 1.0f, 1.0f);
    tiny_step.radiance.at(0, 0)[1] = 1e6f * (1.0f + 1e-3f);
    CHECK(degenerate_reference(tiny_step.radiance, tiny_step.visibility, kSun).empty());
}
