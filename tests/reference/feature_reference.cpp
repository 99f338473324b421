// feature_reference.cpp: the tests' brute-force feature-guided filters,
// written from the contract in the public headers.
#include "reference/feature_reference.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace featref {

namespace {

using spec::Image;

bool finite(double v) { return std::isfinite(v); }

// A guide value, "no value" (`none`) outside its data window.
double guide_at(const Image* g, int x, int y, int c, double none)
{
    return g->contains(x, y) ? g->at(x, y, c) : none;
}

// The weights' view of the beauty: colour channels, luminance, variance.
struct Pixels {
    const Image& beauty;
    const Guides& guides;
    int nc;  // colour channels

    explicit Pixels(const Image& b, const Guides& g)
        : beauty(b), guides(g), nc(std::min(3, b.nchannels)) {}

    double lw(int c) const
    {
        static const double rec709[3] = { 0.2126, 0.7152, 0.0722 };
        return nc == 3 ? rec709[c] : 1.0 / nc;
    }
    double colour(int x, int y, int c) const
    {
        const double v = beauty.at(x, y, c);
        return finite(v) ? v : 0.0;
    }
    double luminance(int x, int y) const
    {
        double l = 0;
        for (int c = 0; c < nc; ++c)
            l += lw(c) * colour(x, y, c);
        return l;
    }
    // Sample variance over the clipped 3x3 window of f(x, y).
    template<class F>
    double sample_variance(int x, int y, F&& f) const
    {
        std::vector<double> v;
        for (int qy = y - 1; qy <= y + 1; ++qy)
            for (int qx = x - 1; qx <= x + 1; ++qx)
                if (beauty.contains(qx, qy))
                    v.push_back(f(qx, qy));
        if (v.size() < 2)
            return 0.0;
        double mean = 0;
        for (double a : v)
            mean += a;
        mean /= double(v.size());
        double s = 0;
        for (double a : v)
            s += (a - mean) * (a - mean);
        return s / double(v.size() - 1);
    }
    double given_variance(int x, int y, int c) const
    {
        const int k  = std::min(c, guides.variance->nchannels - 1);
        const double v = guide_at(guides.variance, x, y, k, 0.0);
        return finite(v) && v > 0 ? v : 0.0;
    }
    double variance(int x, int y, int c) const
    {
        if (guides.variance)
            return given_variance(x, y, c);
        return sample_variance(x, y, [&](int qx, int qy) { return colour(qx, qy, c); });
    }
    double luminance_variance(int x, int y) const
    {
        if (guides.variance) {
            double v = 0;
            for (int c = 0; c < nc; ++c)
                v += lw(c) * lw(c) * given_variance(x, y, c);
            return v;
        }
        return sample_variance(x, y, [&](int qx, int qy) { return luminance(qx, qy); });
    }
};

// features.h: a weight exp(-e) with e past this is 0 (float underflow).
constexpr double max_exponent = 87.0;

double weight_of(double exponent)
{
    return exponent < max_exponent ? std::exp(-exponent) : 0.0;
}

// The exponent (A + N + Z) / 2 of features.h's feature weight; infinite
// across object ids.
double feature_exponent(const Guides& g, const Sigmas& s, int px, int py, int qx, int qy)
{
    if (g.object_id) {
        auto id = [&](int x, int y) -> int64_t {
            if (!g.object_id->contains(x, y))
                return INT64_MIN;
            const double v = g.object_id->at(x, y, 0);
            return std::isnan(v) ? -1 : int64_t(std::nearbyint(v));
        };
        if (id(px, py) != id(qx, qy))
            return INFINITY;
    }
    double sum = 0;
    if (g.albedo && s.albedo > 0) {
        double d2 = 0;
        for (int c = 0; c < g.albedo->nchannels; ++c) {
            double a = guide_at(g.albedo, px, py, c, 0.0), b = guide_at(g.albedo, qx, qy, c, 0.0);
            a = finite(a) ? a : 0.0;
            b = finite(b) ? b : 0.0;
            d2 += (a - b) * (a - b);
        }
        sum += d2 / (s.albedo * s.albedo);
    }
    if (g.normal && s.normal > 0) {
        auto unit = [&](int x, int y, double n[3]) {
            double len2 = 0;
            for (int c = 0; c < 3; ++c) {
                n[c] = guide_at(g.normal, x, y, c, 0.0);
                len2 += n[c] * n[c];
            }
            const double len = std::sqrt(len2);
            for (int c = 0; c < 3; ++c)
                n[c] = finite(len) && len > 0 ? n[c] / len : 0.0;
        };
        double a[3], b[3], d2 = 0;
        unit(px, py, a);
        unit(qx, qy, b);
        for (int c = 0; c < 3; ++c)
            d2 += (a[c] - b[c]) * (a[c] - b[c]);
        sum += d2 / (s.normal * s.normal);
    }
    if (g.depth && s.depth > 0) {
        auto l = [&](int x, int y) {
            const double d = guide_at(g.depth, x, y, 0, INFINITY);
            return finite(d) && d > 0 && d < 1e9 ? std::log(d) : std::log(1e9);
        };
        const double t = l(px, py) - l(qx, qy);
        sum += t * t / (s.depth * s.depth);
    }
    return sum / 2;
}

// Per channel, the weighted mean of the finite values of the neighbours
// `taps(visit)` lists; 0 (counted in `empty`) when none.
template<class Taps>
void weighted_mean(const Image& img, int c0, int c1, Taps&& taps, std::vector<double>& out,
                   long* empty)
{
    for (int c = c0; c < c1; ++c) {
        double num = 0, den = 0;
        taps([&](int qx, int qy, double w) {
            const double v = img.at(qx, qy, c);
            if (finite(v)) {
                num += w * v;
                den += w;
            }
        });
        if (den > 0)
            out.push_back(num / den);
        else {
            out.push_back(0.0);
            if (empty)
                ++*empty;
        }
    }
}

// Every pixel of the ROI: per channel, the weighted mean over the window of
// radius r (clipped to the beauty) where the center weighs 1 and any other
// q weighs weight(x, y, qx, qy).
template<class Weight>
std::vector<double> window_filter(const Image& beauty, const OIIO::ROI& roi, int r,
                                  Weight&& weight, long* empty)
{
    std::vector<double> out;
    for (int y = roi.ybegin; y < roi.yend; ++y)
        for (int x = roi.xbegin; x < roi.xend; ++x)
            weighted_mean(beauty, roi.chbegin, roi.chend, [&](auto visit) {
                for (int qy = y - r; qy <= y + r; ++qy)
                    for (int qx = x - r; qx <= x + r; ++qx)
                        if (beauty.contains(qx, qy))
                            visit(qx, qy, qx == x && qy == y ? 1.0 : weight(x, y, qx, qy));
            }, out, empty);
    return out;
}

}  // namespace

std::vector<double> cross_bilateral(const Image& beauty, const Guides& guides, int size,
                                    double sigma_spatial, double sigma_color,
                                    const Sigmas& sigmas, const OIIO::ROI& roi, long* empty)
{
    const Pixels px(beauty, guides);
    return window_filter(beauty, roi, size / 2, [&](int x, int y, int qx, int qy) {
        const double d2 = double((qx - x) * (qx - x) + (qy - y) * (qy - y));
        double e = d2 / (2 * sigma_spatial * sigma_spatial)
                   + feature_exponent(guides, sigmas, x, y, qx, qy);
        if (sigma_color > 0) {
            double c2 = 0;
            for (int c = 0; c < px.nc; ++c) {
                const double t = px.colour(x, y, c) - px.colour(qx, qy, c);
                c2 += t * t;
            }
            e += c2 / (2 * sigma_color * sigma_color);
        }
        return weight_of(e);
    }, empty);
}

std::vector<double> atrous(const Image& beauty, const Guides& guides, int iterations,
                           double sigma_luminance, const Sigmas& sigmas, const OIIO::ROI& roi,
                           long* empty)
{
    static const double h[5] = { 1.0 / 16, 1.0 / 4, 3.0 / 8, 1.0 / 4, 1.0 / 16 };
    const Pixels first(beauty, guides);
    const int w = beauty.width, ht = beauty.height, nch = beauty.nchannels;
    auto idx = [&](int x, int y) { return size_t(y - beauty.y0) * w + size_t(x - beauty.x0); };
    Image cur = beauty;
    std::vector<double> var(size_t(w) * ht);
    for (int y = beauty.y0; y < beauty.y0 + ht; ++y)
        for (int x = beauty.x0; x < beauty.x0 + w; ++x)
            var[idx(x, y)] = first.luminance_variance(x, y);
    std::vector<double> out;
    for (int it = 0; it < iterations; ++it) {
        const Pixels p(cur, guides);
        const int step = 1 << it;
        const bool last = it == iterations - 1;
        Image next = cur;
        std::vector<double> next_var(var.size());
        for (int y = beauty.y0; y < beauty.y0 + ht; ++y)
            for (int x = beauty.x0; x < beauty.x0 + w; ++x) {
                if (last && !(x >= roi.xbegin && x < roi.xend && y >= roi.ybegin && y < roi.yend))
                    continue;
                double g = 0, gw = 0;
                for (int qy = y - 1; qy <= y + 1; ++qy)
                    for (int qx = x - 1; qx <= x + 1; ++qx)
                        if (beauty.contains(qx, qy)) {
                            const double k = (2 - std::abs(qx - x)) * (2 - std::abs(qy - y));
                            g += k * var[idx(qx, qy)];
                            gw += k;
                        }
                g /= gw;
                const double lp = p.luminance(x, y);
                std::vector<double> ws, vs;  // tap weights, for the variance
                auto taps = [&](auto visit) {
                    for (int ky = -2; ky <= 2; ++ky)
                        for (int kx = -2; kx <= 2; ++kx) {
                            const int qx = x + kx * step, qy = y + ky * step;
                            if (!beauty.contains(qx, qy))
                                continue;
                            double wt = h[kx + 2] * h[ky + 2];
                            if (kx != 0 || ky != 0) {
                                double e = feature_exponent(guides, sigmas, x, y, qx, qy);
                                if (sigma_luminance > 0)
                                    e += std::abs(lp - p.luminance(qx, qy))
                                         / (sigma_luminance * std::sqrt(g) + 1e-10);
                                wt *= weight_of(e);
                            }
                            visit(qx, qy, wt);
                        }
                };
                std::vector<double> values;
                if (last) {
                    weighted_mean(cur, roi.chbegin, roi.chend, taps, out, empty);
                    continue;
                }
                weighted_mean(cur, 0, nch, taps, values, nullptr);
                for (int c = 0; c < nch; ++c)
                    next.values[idx(x, y) * nch + c] = values[size_t(c)];
                double sw = 0, sw2v = 0;
                taps([&](int qx, int qy, double wt) {
                    sw += wt;
                    sw2v += wt * wt * var[idx(qx, qy)];
                });
                next_var[idx(x, y)] = sw2v / (sw * sw);
            }
        cur = next;
        var = next_var;
    }
    return out;
}

std::vector<double> nlmeans(const Image& beauty, const Guides& guides, int search_radius,
                            int patch_radius, double strength, const Sigmas& sigmas,
                            const OIIO::ROI& roi, long* empty)
{
    const Pixels p(beauty, guides);
    const int r = search_radius, f = patch_radius;
    const double k2 = strength * strength;
    // Every pixel's variance, worked out once.
    std::vector<double> var;
    for (int y = beauty.y0; y < beauty.y0 + beauty.height; ++y)
        for (int x = beauty.x0; x < beauty.x0 + beauty.width; ++x)
            for (int c = 0; c < p.nc; ++c)
                var.push_back(p.variance(x, y, c));
    auto variance = [&](int x, int y, int c) {
        return var[(size_t(y - beauty.y0) * beauty.width + size_t(x - beauty.x0)) * p.nc + c];
    };
    auto distance = [&](int ax, int ay, int bx, int by) {
        double d = 0;
        for (int c = 0; c < p.nc; ++c) {
            const double ua = p.colour(ax, ay, c), ub = p.colour(bx, by, c);
            const double va = variance(ax, ay, c), vb = variance(bx, by, c);
            d += ((ua - ub) * (ua - ub) - (va + std::min(va, vb))) / (1e-10 + k2 * (va + vb));
        }
        return d / p.nc;
    };
    return window_filter(beauty, roi, r, [&](int x, int y, int qx, int qy) {
        double sum = 0;
        int count  = 0;
        for (int ny = -f; ny <= f; ++ny)
            for (int nx = -f; nx <= f; ++nx)
                if (beauty.contains(x + nx, y + ny) && beauty.contains(qx + nx, qy + ny)) {
                    sum += distance(x + nx, y + ny, qx + nx, qy + ny);
                    ++count;
                }
        return weight_of(std::max(0.0, sum / count)
                         + feature_exponent(guides, sigmas, x, y, qx, qy));
    }, empty);
}

std::vector<double> modulate(const Image& beauty, const Image& albedo, double epsilon,
                             bool divide, const OIIO::ROI& roi)
{
    std::vector<double> out;
    for (int y = roi.ybegin; y < roi.yend; ++y)
        for (int x = roi.xbegin; x < roi.xend; ++x)
            for (int c = roi.chbegin; c < roi.chend; ++c) {
                const double v = beauty.at(x, y, c);
                if (c >= 3 || !finite(v)) {
                    out.push_back(v);
                    continue;
                }
                double a = albedo.at(x, y, albedo.nchannels == 1 ? 0 : c);
                a = finite(a) ? std::max(0.0, a) : 0.0;
                out.push_back(divide ? v / (a + epsilon) : v * (a + epsilon));
            }
    return out;
}

}  // namespace featref
