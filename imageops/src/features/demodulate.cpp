// demodulate.cpp: albedo demodulation and remodulation.
#include <mcdenoise/demodulate.h>

#include "core/operation.h"
#include "core/window.h"
#include "features/feature_field.h"

#include <algorithm>
#include <cmath>

namespace mcdenoise {

using OIIO::ImageBuf;
using OIIO::ROI;

namespace {

// Colour channel c of `beauty` over `roi` becomes v_c / (a_k + epsilon)
// (`divide`) or v_c * (a_k + epsilon); other channels and non-finite values
// are copied.
bool modulate(const char* op, bool divide, ImageBuf& dst, const ImageBuf& beauty,
              const ImageBuf& albedo, float epsilon, ROI roi, int nthreads)
{
    if (!(epsilon > 0.0f)) {
        dst.errorfmt("{}: epsilon must be > 0, got {}", op, epsilon);
        return false;
    }
    PixelBlock block;
    GuideChannels a;
    if (!resolve_roi(op, dst, beauty, roi) || !check_colour_guide(op, "albedo", dst, albedo, roi)
        || !read_beauty(op, dst, beauty, roi, block)
        || !load_guide_channels(op, dst, albedo, roi, nthreads, a))
        return false;
    ResultPixels result;
    if (!begin_result(op, dst, beauty, { &beauty, &albedo }, roi, result))
        return false;
    const int nc = roi.nchannels();
    parallel_rows(roi, nthreads, [&](int y) {
        const float* in = block.row(y);
        float* out      = result.pixel(roi.xbegin, y);
        for (int i = 0; i < roi.width(); ++i, in += nc, out += result.pixel_stride())
            for (int c = 0; c < nc; ++c) {
                const int ch = roi.chbegin + c;
                const float v = in[c];
                if (ch >= feature_colour_channels || !std::isfinite(v)) {
                    out[c] = v;
                    continue;
                }
                const int k   = std::min(ch, a.nchannels() - 1);
                const float m = std::max(0.0f, a.row(k, y)[i]) + epsilon;
                out[c]        = divide ? v / m : v * m;
            }
    });
    return finish_result(op, dst, result);
}

}  // namespace

bool demodulate(ImageBuf& dst, const ImageBuf& beauty, const ImageBuf& albedo, float epsilon,
                ROI roi, int nthreads)
{
    return modulate("demodulate", true, dst, beauty, albedo, epsilon, roi, nthreads);
}

ImageBuf demodulate(const ImageBuf& beauty, const ImageBuf& albedo, float epsilon, ROI roi,
                    int nthreads)
{
    return value_form([&](ImageBuf& dst) {
        return demodulate(dst, beauty, albedo, epsilon, roi, nthreads);
    });
}

bool remodulate(ImageBuf& dst, const ImageBuf& filtered, const ImageBuf& albedo,
                float epsilon, ROI roi, int nthreads)
{
    return modulate("remodulate", false, dst, filtered, albedo, epsilon, roi, nthreads);
}

ImageBuf remodulate(const ImageBuf& filtered, const ImageBuf& albedo, float epsilon, ROI roi,
                    int nthreads)
{
    return value_form([&](ImageBuf& dst) {
        return remodulate(dst, filtered, albedo, epsilon, roi, nthreads);
    });
}

}  // namespace mcdenoise
