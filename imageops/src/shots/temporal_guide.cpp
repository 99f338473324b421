// temporal_guide.cpp: the weighted temporal mean of the centre frame's
// colour and features and its variance, from each neighbour's weight at
// offset 0.
#include "shots/temporal_guide.h"

#include "core/window.h"

#include <algorithm>
#include <vector>

namespace mcdenoise {

using OIIO::ROI;

TemporalGuide temporal_guide(const std::vector<NlmFrame>& frames, const ROI& region,
                             const ROI& dw, int patch_radius, float strength, int nthreads)
{
    const NlmFrame& centre = frames.front();
    const int nc   = centre.colour->nchannels();
    const int dims = centre.features->dims.nchannels();
    const auto lw  = luminance_weights(nc);
    TemporalGuide g { { Planes<float>(region, nc), Plane<float>(region) },
                      { Planes<float>(region, nc), Plane<float>(region) },
                      { Planes<float>(region, dims), IdPlane() },
                      {} };
    std::vector<Plane<float>>& weights = g.weights;
    for (size_t k = 1; k < frames.size(); ++k) {
        weights.emplace_back(region);
        match_weights(frames[k], *centre.colour, *centre.variance, dw, patch_radius, strength,
                      nthreads, weights.back());
    }
    // Row by row, each plane: the centre's, plus each neighbour's times its
    // weight (squared for the variance), over the total weight (squared).
    const size_t nf = frames.size();
    parallel_rows(region, nthreads, [&](int y) {
        const int x0 = region.xbegin, n = region.width();
        std::vector<float> total(size_t(n), 1.0f);
        for (size_t k = 1; k < nf; ++k) {
            const float* w = weights[k - 1].from(x0, y);
            for (int i = 0; i < n; ++i)
                total[size_t(i)] += w[i];
        }
        // The weighted mean of plane p of `planes(f)` over the frames into
        // `out`, each frame's weight squared with `squared`.
        const auto mean = [&](auto&& planes, size_t p, bool squared, float* out) {
            const float* c = planes(frames[0]).from(int(p), x0, y);
            std::copy(c, c + n, out);
            for (size_t k = 1; k < nf; ++k) {
                const float* w = weights[k - 1].from(x0, y);
                const float* v = planes(frames[k]).from(int(p), x0, y);
                for (int i = 0; i < n; ++i)
                    out[i] += (squared ? w[i] * w[i] : w[i]) * v[i];
            }
            for (int i = 0; i < n; ++i)
                out[i] = squared ? out[i] / (total[size_t(i)] * total[size_t(i)])
                                 : out[i] / total[size_t(i)];
        };
        const auto colours  = [](const NlmFrame& f) -> const auto& { return f.colour->colour; };
        const auto variances = [](const NlmFrame& f) -> const auto& { return f.variance->colour; };
        const auto features = [](const NlmFrame& f) -> const auto& { return f.features->dims; };
        float* lum     = g.colour.luminance.from(x0, y);
        float* lum_var = g.variance.luminance.from(x0, y);
        std::fill(lum, lum + n, 0.0f);
        std::fill(lum_var, lum_var + n, 0.0f);
        for (int c = 0; c < nc; ++c) {
            float* u = g.colour.colour.from(c, x0, y);
            float* v = g.variance.colour.from(c, x0, y);
            mean(colours, size_t(c), false, u);
            mean(variances, size_t(c), true, v);
            const float l = lw[size_t(c)], l2 = l * l;
            for (int i = 0; i < n; ++i) {
                lum[i] += l * u[i];
                lum_var[i] += l2 * v[i];
            }
        }
        for (int d = 0; d < dims; ++d)
            mean(features, size_t(d), false, g.features.dims.from(d, x0, y));
    });
    return g;
}

}  // namespace mcdenoise
