// cross_bilateral.cpp: the joint (cross) bilateral filter: spatial, feature
// and optional colour weights, one window offset at a time over contiguous
// rows.
#include <mcdenoise/cross_bilateral.h>

#include "core/operation.h"
#include "core/window.h"
#include "features/feature_field.h"
#include "features/weighted_sums.h"
#include "walkers/offset_walk.h"

namespace mcdenoise {

using OIIO::ImageBuf;
using OIIO::ROI;

namespace {

// Add the colour exponent |c_p - c_q|^2 * scale of center (x0 + i, y) and
// neighbour (x0 + i + dx, y + dy) to e[i], for i < n.
void add_colour_exponent(const ColourField& colour, float scale, int y, int x0, int n, int dx,
                         int dy, float* e)
{
    for (int c = 0; c < colour.nchannels(); ++c) {
        const float* a = colour.colour.from(c, x0, y);
        const float* b = colour.colour.from(c, x0 + dx, y + dy);
        for (int i = 0; i < n; ++i) {
            const float t = a[i] - b[i];
            e[i] += scale * (t * t);
        }
    }
}

}  // namespace

bool cross_bilateral(ImageBuf& dst, const ImageBuf& beauty, const Guides& guides, int size,
                     float sigma_spatial, float sigma_color, const FeatureSigmas& sigmas,
                     ROI roi, int nthreads)
{
    const char* op = "cross_bilateral";
    if (!check_window_op(op, dst, beauty, size, roi))
        return false;
    if (!(sigma_spatial > 0.0f)) {
        dst.errorfmt("{}: sigma_spatial must be > 0, got {}", op, sigma_spatial);
        return false;
    }
    if (!check_feature_guides(op, dst, guides, roi))
        return false;
    const int r         = size / 2;
    const ROI dw        = beauty.roi();
    ROI region          = grow_and_clip(roi, r, dw);
    region.chbegin      = 0;
    region.chend        = beauty.nchannels();
    const bool by_color = sigma_color > 0.0f;
    PixelBlock block;
    FeatureField features;
    if (!read_beauty(op, dst, beauty, region, block)
        || !load_feature_field(op, dst, guides, sigmas, region, nthreads, features))
        return false;
    const ColourField colour = by_color ? colour_field(block, region, nthreads) : ColourField {};
    const SumSource src = sum_source(block, roi.chbegin, roi.chend, region, nthreads);
    block = {};
    ResultPixels result;
    if (!begin_result(op, dst, beauty,
                      { &beauty, guides.object_id, guides.normal, guides.depth, guides.albedo },
                      roi, result))
        return false;
    const float spatial_scale = float(1.0 / (2.0 * double(sigma_spatial) * sigma_spatial));
    const float colour_scale  = by_color ? float(1.0 / (2.0 * double(sigma_color) * sigma_color))
                                         : 0.0f;
    parallel_rows(roi, nthreads, [&](int y) {
        const FlushDenormals flush;
        for_each_segment(roi.xbegin, roi.xend, [&](int x0, int n) {
            WeightedSums sums(0, src.nchannels(), n, src.masked());
            const size_t len = static_cast<size_t>(n);
            std::vector<float> e(len), w(len);
            for_each_offset(y, x0, n, r, 1, dw, [&](const Offset& o) {
                const int xa = x0 + o.i0;
                if (o.centre()) {
                    std::fill(w.begin() + o.i0, w.begin() + o.i1, 1.0f);
                } else {
                    std::fill(e.begin() + o.i0, e.begin() + o.i1,
                              spatial_scale * float(o.dx * o.dx + o.dy * o.dy));
                    if (by_color)
                        add_colour_exponent(colour, colour_scale, y, xa, o.count(), o.dx, o.dy,
                                            e.data() + o.i0);
                    features.weights_row(y, xa, o.count(), o.dx, o.dy, e.data() + o.i0, 1.0f,
                                         w.data() + o.i0);
                }
                sums.add(w.data(), src, x0 + o.dx, y + o.dy, o.i0, o.i1);
            });
            result.empty_windows += sums.write(result.pixel(x0, y), result.pixel_stride());
        });
    });
    return finish_result(op, dst, result);
}

ImageBuf cross_bilateral(const ImageBuf& beauty, const Guides& guides, int size,
                         float sigma_spatial, float sigma_color, const FeatureSigmas& sigmas,
                         ROI roi, int nthreads)
{
    return value_form([&](ImageBuf& dst) {
        return cross_bilateral(dst, beauty, guides, size, sigma_spatial, sigma_color, sigmas,
                               roi, nthreads);
    });
}

}  // namespace mcdenoise
