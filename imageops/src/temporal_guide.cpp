// temporal_guide.cpp: the weighted temporal mean of the centre frame's
// colour and features and its variance, from each neighbour's weight at
// offset 0.
#include "temporal_guide.h"

#include "window.h"

namespace mcdenoise {

using OIIO::ROI;

TemporalGuide temporal_guide(const std::vector<NlmFrame>& frames, const ROI& region,
                             const ROI& dw, int patch_radius, float strength, int nthreads)
{
    const NlmFrame& centre = frames.front();
    const int nc   = centre.colour->nchannels();
    const int dims = centre.features->dims.nchannels();
    const auto lw  = luminance_weights(nc);
    std::vector<Plane<float>> weights;
    for (size_t k = 1; k < frames.size(); ++k) {
        weights.emplace_back(region);
        match_weights(frames[k], *centre.colour, *centre.variance, dw, patch_radius, strength,
                      nthreads, weights.back());
    }
    TemporalGuide g { { Planes<float>(region, nc), Plane<float>(region) },
                      { Planes<float>(region, nc), Plane<float>(region) },
                      { Planes<float>(region, dims), IdPlane() } };
    const size_t nf = frames.size();
    parallel_rows(region, nthreads, [&](int y) {
        for (int x = region.xbegin; x < region.xend; ++x) {
            const size_t i = g.colour.colour.offset(x, y);
            float total = 1.0f;
            for (size_t k = 1; k < nf; ++k)
                total += weights[k - 1].values[i];
            // The weighted mean over the frames of plane p of `planes(f)`
            // at (x, y), each frame's weight to the power `power`.
            const auto mean = [&](auto&& planes, size_t p, int power) {
                const auto& centre_planes = planes(frames[0]);
                float sum = centre_planes.values[p][centre_planes.offset(x, y)];
                for (size_t k = 1; k < nf; ++k) {
                    const float w = weights[k - 1].values[i];
                    const auto& own = planes(frames[k]);
                    sum += (power == 2 ? w * w : w) * own.values[p][own.offset(x, y)];
                }
                return power == 2 ? sum / (total * total) : sum / total;
            };
            const auto colours  = [](const NlmFrame& f) -> const auto& { return f.colour->colour; };
            const auto variances = [](const NlmFrame& f) -> const auto& { return f.variance->colour; };
            const auto features = [](const NlmFrame& f) -> const auto& { return f.features->dims; };
            float lum = 0.0f, lum_var = 0.0f;
            for (int c = 0; c < nc; ++c) {
                const float u = mean(colours, size_t(c), 1);
                const float v = mean(variances, size_t(c), 2);
                g.colour.colour.values[size_t(c)][i]   = u;
                g.variance.colour.values[size_t(c)][i] = v;
                lum += lw[size_t(c)] * u;
                lum_var += lw[size_t(c)] * lw[size_t(c)] * v;
            }
            for (int d = 0; d < dims; ++d)
                g.features.dims.values[size_t(d)][i] = mean(features, size_t(d), 1);
            g.colour.luminance.values[i]   = lum;
            g.variance.luminance.values[i] = lum_var;
        }
    });
    return g;
}

}  // namespace mcdenoise
