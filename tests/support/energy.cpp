// energy.cpp: the frame mean and brightest-pixel energy ratios of energy.h.
#include "energy.h"

#include <mcdenoise/mcdenoise.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

namespace testimg {

namespace {

/// Per-pixel Rec. 709 luminance of the first three channels, in scanline
/// order over the data window (non-finite values as 0).
std::vector<double> luminances(const OIIO::ImageBuf& img)
{
    const OIIO::ROI dw = img.roi();
    std::vector<double> out;
    out.reserve(size_t(dw.npixels()));
    const double w[3] = { 0.2126, 0.7152, 0.0722 };
    for (int y = dw.ybegin; y < dw.yend; ++y)
        for (int x = dw.xbegin; x < dw.xend; ++x) {
            double l = 0.0;
            for (int c = 0; c < 3; ++c) {
                const float v = img.getchannel(x, y, 0, c);
                l += std::isfinite(v) ? w[c] * v : 0.0;
            }
            out.push_back(l);
        }
    return out;
}

}  // namespace

double frame_mean_ratio(const OIIO::ImageBuf& img, const OIIO::ImageBuf& ref)
{
    const std::vector<double> a = luminances(img), b = luminances(ref);
    return std::accumulate(a.begin(), a.end(), 0.0) / std::accumulate(b.begin(), b.end(), 0.0);
}

double brightest_energy_ratio(const OIIO::ImageBuf& img, const OIIO::ImageBuf& ref,
                              double fraction)
{
    const std::vector<double> a = luminances(img), b = luminances(ref);
    std::vector<size_t> order(b.size());
    std::iota(order.begin(), order.end(), size_t(0));
    const size_t n = std::max<size_t>(1, size_t(std::ceil(fraction * double(b.size()))));
    std::partial_sort(order.begin(), order.begin() + std::ptrdiff_t(n), order.end(),
                      [&](size_t i, size_t j) { return b[i] > b[j]; });
    double kept = 0.0, total = 0.0;
    for (size_t k = 0; k < n; ++k) {
        kept += a[order[k]];
        total += b[order[k]];
    }
    return kept / total;
}

OIIO::ImageBuf previous_preset(const Render& r)
{
    mcdenoise::Guides g = r.guides();
    g.object_id = g.half_a = g.half_b = nullptr;
    return mcdenoise::nlmeans(mcdenoise::clamp_fireflies(r.beauty, {}, 2.0f, 2), g, 5, 1,
                              mcdenoise::denoise_measured_strength,
                              mcdenoise::denoise_feature_sigmas);
}

}  // namespace testimg
