#include "metrics/pixel_error.hpp"

#include "metrics/comparable_pair.hpp"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <cmath>
#include <limits>

namespace canopy {

namespace {

// A read-only view of an Image as an OIIO buffer; OIIO wants a non-const pointer but compare()
// never writes through it.
OIIO::ImageBuf wrap_as_image_buf(const Image& image) {
    OIIO::ImageSpec spec(image.width, image.height, 4, OIIO::TypeDesc::FLOAT);
    return OIIO::ImageBuf(spec, const_cast<float*>(image.pixels.data()));
}

}  // namespace

PixelError compute_pixel_error(const Image& test, const Image& reference) {
    const ComparablePair pair = make_comparable_pair(test, reference);
    PixelError result;
    result.included_pixels = pair.included_count;
    if (pair.included_count == 0) {
        const double nan = std::numeric_limits<double>::quiet_NaN();
        result.mae = result.rmse = result.psnr = result.max_error = nan;
        return result;
    }

    const OIIO::ImageBuf test_buf = wrap_as_image_buf(pair.test);
    const OIIO::ImageBuf reference_buf = wrap_as_image_buf(pair.reference);
    OIIO::ROI rgb_only = OIIO::get_roi(test_buf.spec());
    rgb_only.chbegin = 0;
    rgb_only.chend = 3;
    const float never = std::numeric_limits<float>::max();  // thresholds are irrelevant here
    const OIIO::ImageBufAlgo::CompareResults compared =
        OIIO::ImageBufAlgo::compare(test_buf, reference_buf, never, never, rgb_only);

    // Excluded pixels contribute zero error, so only the denominator needs fixing.
    const double all_pixels = double(test.width) * double(test.height);
    const double scale = all_pixels / double(pair.included_count);
    result.mae = compared.meanerror * scale;
    result.rmse = compared.rms_error * std::sqrt(scale);
    result.psnr = result.rmse > 0.0 ? 20.0 * std::log10(1.0 / result.rmse) : std::numeric_limits<double>::infinity();
    result.max_error = compared.maxerror;
    result.max_x = compared.maxx;
    result.max_y = compared.maxy;
    return result;
}

}  // namespace canopy
