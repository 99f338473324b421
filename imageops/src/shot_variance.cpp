// shot_variance.cpp: the spread of each pixel's colour across the frames
// that agree with the centre there, as the frames' variance.
#include "shot_variance.h"

#include "window.h"

#include <algorithm>
#include <array>
#include <vector>

namespace mcdenoise {

using OIIO::ROI;

namespace {

/// How many standard deviations the box means of a neighbour and the
/// centre may differ by.
constexpr float agreement_sigmas = 3.0f;
/// How many times the variance of independent pixels' mean a box mean's
/// variance is taken to be (see shot_variance.h).
constexpr float correlated_pixels = 2.0f;
/// The feature weight (features.h) a neighbour's pixel needs to count.
constexpr float min_feature_weight = 0.25f;

// The mean of `value(x, y)` over the box of `agreement_radius` around each
// pixel of `region`, clipped to `dw`, into `out` (over `region`).
template<class Value>
void box_mean(Value&& value, const ROI& region, const ROI& dw, int nthreads, Plane<float>& out)
{
    const ROI cols = grow_and_clip(region, agreement_radius, dw);
    parallel_rows(region, nthreads, [&](int y) {
        const Span ys = clip_window(y, agreement_radius, dw.ybegin, dw.yend);
        const float rows = float(ys.end - ys.begin);
        std::vector<float> column(size_t(cols.width()));
        for (int x = cols.xbegin; x < cols.xend; ++x) {
            float sum = 0.0f;
            for (int qy = ys.begin; qy < ys.end; ++qy)
                sum += value(x, qy);
            column[size_t(x - cols.xbegin)] = sum / rows;
        }
        for (int x = region.xbegin; x < region.xend; ++x) {
            const Span xs = clip_window(x, agreement_radius, dw.xbegin, dw.xend);
            float sum = 0.0f;
            for (int qx = xs.begin; qx < xs.end; ++qx)
                sum += column[size_t(qx - cols.xbegin)];
            out.at(x, y) = sum / float(xs.end - xs.begin);
        }
    });
}

// Whether each neighbour agrees with the centre at each pixel of `region`
// (1 or 0), one plane per neighbour.
std::vector<Plane<float>> agreement(const std::vector<NlmFrame>& frames,
                                    const std::vector<const Plane<float>*>& faithful,
                                    const ROI& region, const ROI& dw, int nthreads)
{
    const NlmFrame& centre = frames[0];
    const int nc           = centre.colour->nchannels();
    const float box        = float((2 * agreement_radius + 1) * (2 * agreement_radius + 1));
    // The allowed squared difference of the box means, summed over the
    // colour channels.
    Plane<float> allowed(region, 0.0f);
    Plane<float> mean(region);
    for (int c = 0; c < nc; ++c) {
        box_mean([&](int x, int y) { return *centre.variance->colour.from(c, x, y); }, region,
                 dw, nthreads, mean);
        for (size_t i = 0; i < allowed.values.size(); ++i)
            allowed.values[i] += agreement_sigmas * agreement_sigmas * 2.0f * mean.values[i]
                                 * correlated_pixels / box;
    }
    std::vector<Plane<float>> out;
    for (size_t k = 1; k < frames.size(); ++k) {
        const NlmFrame& f       = frames[k];
        const Plane<float>& put = *faithful[k - 1];
        Plane<float> apart(region, 0.0f);
        for (int c = 0; c < nc; ++c) {
            box_mean([&](int x, int y) {
                         return *f.colour->colour.from(c, x, y) - *centre.colour->colour.from(c, x, y);
                     },
                     region, dw, nthreads, mean);
            for (size_t i = 0; i < apart.values.size(); ++i)
                apart.values[i] += mean.values[i] * mean.values[i];
        }
        Plane<float> agrees(region);
        parallel_rows(region, nthreads, [&](int y) {
            const int n = region.width();
            const std::vector<float> none(size_t(n), 0.0f);
            std::vector<float> features(static_cast<size_t>(n));
            centre.features->weights_row(y, region.xbegin, n, 0, 0, none.data(), 1.0f,
                                         features.data(), *f.features);
            for (int x = region.xbegin; x < region.xend; ++x)
                agrees.at(x, y) = put.at(x, y) > 0.0f
                                          && features[size_t(x - region.xbegin)] >= min_feature_weight
                                          && apart.at(x, y) <= allowed.at(x, y)
                                      ? 1.0f
                                      : 0.0f;
        });
        out.push_back(std::move(agrees));
    }
    return out;
}

}  // namespace

std::vector<VarianceField> shot_variance(const std::vector<NlmFrame>& frames,
                                         const std::vector<const Plane<float>*>& faithful,
                                         const ROI& region, const ROI& dw, int nthreads)
{
    const bool any = std::any_of(faithful.begin(), faithful.end(), [](const Plane<float>* p) {
        return std::any_of(p->values.begin(), p->values.end(), [](float v) { return v > 0.0f; });
    });
    std::vector<VarianceField> out;
    if (!any || frames.size() < 3)
        return out;
    const int nc  = frames[0].colour->nchannels();
    const auto lw = luminance_weights(nc);
    const std::vector<Plane<float>> agrees = agreement(frames, faithful, region, dw, nthreads);
    for (size_t k = 0; k < frames.size(); ++k)
        out.push_back({ Planes<float>(region, nc), Plane<float>(region) });
    parallel_rows(region, nthreads, [&](int y) {
        for (int x = region.xbegin; x < region.xend; ++x) {
            double n = 1.0;
            for (const Plane<float>& a : agrees)
                n += a.at(x, y);
            std::array<float, feature_colour_channels> spread {};
            for (int c = 0; c < nc && n >= 3.0; ++c) {
                double sum = *frames[0].colour->colour.from(c, x, y), sum2 = sum * sum;
                for (size_t k = 1; k < frames.size(); ++k) {
                    const double v = agrees[k - 1].at(x, y) * *frames[k].colour->colour.from(c, x, y);
                    sum += v;
                    sum2 += v * v;
                }
                spread[size_t(c)] = float(std::max(0.0, (sum2 - sum * sum / n) / (n - 1.0)));
            }
            for (size_t k = 0; k < frames.size(); ++k) {
                float lum = 0.0f;
                for (int c = 0; c < nc; ++c) {
                    const float v = std::max(*frames[k].variance->colour.from(c, x, y),
                                             spread[size_t(c)]);
                    *out[k].colour.from(c, x, y) = v;
                    lum += lw[size_t(c)] * lw[size_t(c)] * v;
                }
                out[k].luminance.at(x, y) = lum;
            }
        }
    });
    return out;
}

}  // namespace mcdenoise
