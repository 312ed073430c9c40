// A reference that cannot tell techniques apart: every case scored against it looks "perfect"
// (PSNR inf, FLIP 0, visibility RMSE 0) whatever it draws. A camera inside a closed sphere, an area
// light inside geometry or a shadow that falls outside the view give such references; the run
// flags their cases in every table and a claim's verdict never rests on one.
#pragma once

#include "core/image.hpp"

#include <string>
#include <vector>

namespace canopy {

struct ReferenceLighting {
    bool shadow_light = false;  // the scene has a shadow-casting light (the visibility image's R and G mean something)
    bool area_light = false;    // that light is an area light: a shadow it casts in view has a penumbra
};

// Why the reference (`radiance`, and `visibility` as render_reference writes it: R the light's
// visible fraction, G 1 where the pixel sees a surface facing the light) is degenerate, each reason
// a short phrase for tables ("no lit pixels"); empty when it is not:
//   "uniform image"  every pixel has the same radiance (to 1e-6 of the largest);
//   "no lit pixels"  the shadow light reaches no surface the camera sees;
//   "no penumbra"    an area light lights the view, and no pixel facing it is partly shadowed.
std::vector<std::string> degenerate_reference(const Image& radiance, const Image& visibility, ReferenceLighting lighting);

// The reasons joined for a table cell: "degenerate reference: no lit pixels, uniform image"; "" for none.
std::string degenerate_reference_text(const std::vector<std::string>& reasons);

}  // namespace canopy
