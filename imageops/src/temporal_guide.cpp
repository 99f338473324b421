// temporal_guide.cpp: the weighted temporal mean of the centre frame's
// colour and its variance, through one NL-means pass at offset 0.
#include "temporal_guide.h"

#include "window.h"

namespace mcdenoise {

using OIIO::ROI;

namespace {

// Over `region`: the frame's colour channels, its variance channels,
// `own` (1 for the centre, 0 for a neighbour) and its feature dimensions,
// as sums read them.
SumSource guide_values(const NlmFrame& frame, const ROI& region, float own)
{
    const int nc   = frame.colour->nchannels();
    const int dims = frame.features->dims.nchannels();
    SumSource out(region, 2 * nc + 1 + dims);
    for (int y = region.ybegin; y < region.yend; ++y) {
        const int x = region.xbegin, w = region.width();
        for (int c = 0; c < nc; ++c) {
            std::copy_n(frame.colour->colour.from(c, x, y), w, out.row(c, y));
            std::copy_n(frame.variance->colour.from(c, x, y), w, out.row(nc + c, y));
        }
        std::fill_n(out.row(2 * nc, y), w, own);
        for (int d = 0; d < dims; ++d)
            std::copy_n(frame.features->dims.from(d, x, y), w, out.row(2 * nc + 1 + d, y));
    }
    return out;
}

}  // namespace

TemporalGuide temporal_guide(const std::vector<NlmFrame>& frames, const ROI& region,
                             const ROI& dw, int patch_radius, float strength, int nthreads)
{
    const int nc   = frames.front().colour->nchannels();
    const int dims = frames.front().features->dims.nchannels();
    const auto lw  = luminance_weights(nc);
    std::vector<SumSource> values;
    for (const NlmFrame& f : frames)
        values.push_back(guide_values(f, region, f.own ? 1.0f : 0.0f));
    std::vector<NlmFrame> at_pixel = frames;
    for (size_t i = 0; i < frames.size(); ++i) {
        at_pixel[i].values        = &values[i];
        at_pixel[i].search_radius = 0;
    }
    ResultPixels result;
    ROI all    = region;
    all.chbegin = 0;
    all.chend   = 2 * nc + 1 + dims;
    result.use_buffer(all);
    nlmeans_frames(at_pixel, *frames.front().colour, *frames.front().variance, dw, patch_radius,
                   strength, nthreads, result);
    TemporalGuide g { { Planes<float>(region, nc), Plane<float>(region) },
                      { Planes<float>(region, nc), Plane<float>(region) },
                      { Planes<float>(region, dims), IdPlane() } };
    parallel_rows(region, nthreads, [&](int y) {
        for (int x = region.xbegin; x < region.xend; ++x) {
            const float* m = result.pixel(x, y);
            const size_t i = g.colour.colour.offset(x, y);
            float lum = 0.0f, lum_var = 0.0f;
            for (int c = 0; c < nc; ++c) {
                const float v = m[nc + c] * m[2 * nc];  // (sum w v / sum w) / sum w
                g.colour.colour.values[size_t(c)][i]   = m[c];
                g.variance.colour.values[size_t(c)][i] = v;
                lum += lw[size_t(c)] * m[c];
                lum_var += lw[size_t(c)] * lw[size_t(c)] * v;
            }
            for (int d = 0; d < dims; ++d)
                g.features.dims.values[size_t(d)][i] = m[2 * nc + 1 + d];
            g.colour.luminance.values[i]   = lum;
            g.variance.luminance.values[i] = lum_var;
        }
    });
    return g;
}

}  // namespace mcdenoise
