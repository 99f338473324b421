// feature_regression.cpp: EXPERIMENT of issue 20 (reverted in the next
// commit; docs/denoise.md has its figures). Off unless an environment
// variable asks for it: MCD_FR=[a][n][d] (albedo, normal, log depth as
// regressors), MCD_FR_LAMBDA (ridge), MCD_FR_SA/SN/SD (feature fall-off
// factors of the regression's weights), MCD_FR_K (strength factor),
// MCD_FR_R (search radius), MCD_FR_OFF=1 (plain nlmeans with MCD_FR_K and
// MCD_FR_R); MCD_SEL=k1,k2,.. (per-pixel choice among strengths by
// half-buffer cross-validation, MCD_SEL_R box radius, MCD_SEL_C variance
// correction, MCD_SEL_DEBUG=1 prints the estimates).
//
// The weighted first-order regression of the colour on the features. The weighted moments the fit needs (the means of the
// features, of their products and of colour times feature) are NL-means
// averages of product channels stacked after the beauty, so one `nlmeans`
// pass with the colour's weights gives them all; each pixel then solves its
// small ridge system.
#include "feature_regression.h"

#include <mcdenoise/denoise.h>
#include <mcdenoise/nlmeans.h>
#include <mcdenoise/simple.h>

#include "feature_field.h"
#include "window.h"

#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace mcdenoise {

using OIIO::ImageBuf;
using OIIO::ROI;

namespace {

constexpr int max_features = 8;

struct FeatureSource {
    const ImageBuf* image;
    int channel;
};

std::vector<FeatureSource> regressors(const Guides& g)
{
    const char* env = std::getenv("MCD_FR");
    const std::string set = env ? env : "";
    std::vector<FeatureSource> out;
    for (char c : set) {
        if (c == 'a' && g.albedo)
            for (int i = 0; i < 3; ++i)
                out.push_back({ g.albedo, i });
        if (c == 'n' && g.normal)
            for (int i = 0; i < 3; ++i)
                out.push_back({ g.normal, i });
        if (c == 'd' && g.depth)
            out.push_back({ g.depth, 0 });
    }
    return out;
}

float env_float(const char* name, float fallback)
{
    const char* v = std::getenv(name);
    return v ? float(std::atof(v)) : fallback;
}


// Experimental: per-pixel choice among NL-means strengths by half-buffer
// cross-validation, the halves filtered with the full image's weights.
bool select_strength(ImageBuf& dst, const DenoiseFrame& frame, const ROI& roi, int nthreads,
                     const std::vector<float>& ks)
{
    const ImageBuf& beauty = frame.clamped;
    const ImageBuf& original = *frame.original;
    const int nb = beauty.nchannels(), nc = colour_channels(nb);
    const int nm = nb + 2 * nc;
    const ROI region = beauty.roi();
    ROI all = region;
    all.chbegin = 0;
    all.chend   = nm;
    OIIO::ImageSpec spec(all, OIIO::TypeDesc::FLOAT);
    for (int c = 0; c < nb; ++c)
        spec.channelnames[size_t(c)] = beauty.spec().channel_name(c);
    spec.alpha_channel = beauty.spec().alpha_channel;
    ImageBuf source(spec);
    parallel_rows(region, nthreads, [&](int y) {
        std::vector<float> px(static_cast<size_t>(nb)), raw(static_cast<size_t>(original.nchannels()));
        for (int x = region.xbegin; x < region.xend; ++x) {
            beauty.getpixel(x, y, px.data(), nb);
            original.getpixel(x, y, raw.data(), int(raw.size()));
            float* out = static_cast<float*>(source.pixeladdr(x, y));
            for (int c = 0; c < nb; ++c)
                out[c] = px[size_t(c)];
            for (int c = 0; c < nc; ++c) {
                const float s = raw[size_t(c)] != 0.0f ? px[size_t(c)] / raw[size_t(c)] : 1.0f;
                out[nb + c]      = s * frame.guides.half_a->getchannel(x, y, 0, c);
                out[nb + nc + c] = s * frame.guides.half_b->getchannel(x, y, 0, c);
            }
        }
    });
    const int nk = int(ks.size());
    std::vector<ImageBuf> cand(static_cast<size_t>(nk)), err(static_cast<size_t>(nk));
    ROI moment_roi    = roi;
    moment_roi.chbegin = 0;
    moment_roi.chend   = nm;
    for (int j = 0; j < nk; ++j)
        if (!nlmeans(cand[size_t(j)], source, frame.guides, denoise_search_radius, denoise_patch_radius,
                     frame.strength * ks[size_t(j)], denoise_feature_sigmas, moment_roi, nthreads))
            return false;
    const int r = int(env_float("MCD_SEL_R", 3));
    const float corr = env_float("MCD_SEL_C", 0.25f);
    ROI eroi = roi;
    eroi.chbegin = 0;
    eroi.chend = 1;
    for (int j = 0; j < nk; ++j) {
        ImageBuf e(OIIO::ImageSpec(eroi, OIIO::TypeDesc::FLOAT));
        parallel_rows(roi, nthreads, [&](int y) {
            for (int x = roi.xbegin; x < roi.xend; ++x) {
                const float* f = static_cast<const float*>(cand[size_t(j)].pixeladdr(x, y));
                const float* f0 = static_cast<const float*>(cand[0].pixeladdr(x, y));
                const float* src = static_cast<const float*>(source.pixeladdr(x, y));
                double sum = 0;
                for (int c = 0; c < nc; ++c) {
                    const double fa = f[nb + c], fb = f[nb + nc + c];
                    const double a = src[nb + c], b = src[nb + nc + c];
                    const double v = 0.5 * ((fa - b) * (fa - b) + (fb - a) * (fb - a))
                                     - corr * (fa - fb) * (fa - fb);
                    sum += v / (double(f0[c]) * f0[c] + 0.01);
                }
                *static_cast<float*>(e.pixeladdr(x, y)) = float(sum);
            }
        });
        if (r > 0) {
            if (!mean(err[size_t(j)], e, 2 * r + 1, eroi, nthreads))
                return false;
        } else
            err[size_t(j)].copy(e);
    }
    if (std::getenv("MCD_SEL_DEBUG"))
        for (int j = 0; j < nk; ++j) {
            double tot = 0;
            for (int y = roi.ybegin; y < roi.yend; ++y)
                for (int x = roi.xbegin; x < roi.xend; ++x)
                    tot += *static_cast<const float*>(err[size_t(j)].pixeladdr(x, y));
            std::fprintf(stderr, "k %g est %g\n", ks[size_t(j)], tot / double(roi.npixels()) / nc);
        }
    ImageBuf out(OIIO::ImageSpec(roi, OIIO::TypeDesc::FLOAT));
    for (int c = 0; c < nb; ++c)
        out.specmod().channelnames[size_t(c)] = beauty.spec().channel_name(c);
    parallel_rows(roi, nthreads, [&](int y) {
        for (int x = roi.xbegin; x < roi.xend; ++x) {
            int best = 0;
            float be = *static_cast<const float*>(err[0].pixeladdr(x, y));
            for (int j = 1; j < nk; ++j) {
                const float ej = *static_cast<const float*>(err[size_t(j)].pixeladdr(x, y));
                if (ej < be) {
                    be = ej;
                    best = j;
                }
            }
            const float* f = static_cast<const float*>(cand[size_t(best)].pixeladdr(x, y));
            std::copy(f, f + nb, static_cast<float*>(out.pixeladdr(x, y)));
        }
    });
    return OIIO::ImageBufAlgo::copy(dst, out, OIIO::TypeUnknown, roi, nthreads);
}

}  // namespace

bool regression_average(ImageBuf& dst, const DenoiseFrame& frame, const ROI& roi, int nthreads)
{
    if (const char* sel = std::getenv("MCD_SEL"); sel && frame.guides.half_a && frame.original) {
        std::vector<float> ks;
        std::string list = sel;
        size_t pos = 0;
        while (pos < list.size()) {
            const size_t next = list.find(',', pos);
            ks.push_back(float(std::atof(list.substr(pos, next - pos).c_str())));
            if (next == std::string::npos)
                break;
            pos = next + 1;
        }
        return select_strength(dst, frame, roi, nthreads, ks);
    }
    const ImageBuf& beauty = frame.clamped;
    const std::vector<FeatureSource> feats = regressors(frame.guides);
    const int k = int(feats.size());
    if (k == 0 || env_float("MCD_FR_OFF", 0.0f) > 0.0f)
        return nlmeans(dst, beauty, frame.guides, int(env_float("MCD_FR_R", 5)), denoise_patch_radius,
                       frame.strength * env_float("MCD_FR_K", 1.0f), denoise_feature_sigmas, roi, nthreads);
    const int nb = beauty.nchannels();
    const int nc = colour_channels(nb);
    const int npairs = k * (k + 1) / 2;
    const int nm     = nb + k + npairs + nc * k;
    const ROI region = beauty.roi();
    // The source: the beauty, then f_i, f_i f_j (i <= j), c_m f_i.
    ROI all = region;
    all.chbegin = 0;
    all.chend   = nm;
    OIIO::ImageSpec spec(all, OIIO::TypeDesc::FLOAT);
    for (int c = 0; c < nb; ++c)
        spec.channelnames[size_t(c)] = beauty.spec().channel_name(c);
    spec.alpha_channel = beauty.spec().alpha_channel;
    ImageBuf source(spec);
    const float depth_scale = env_float("MCD_FR_DEPTH", 1.0f);
    parallel_rows(region, nthreads, [&](int y) {
        std::vector<float> px(static_cast<size_t>(nb)), f(static_cast<size_t>(k));
        for (int x = region.xbegin; x < region.xend; ++x) {
            beauty.getpixel(x, y, px.data(), nb);
            for (int i = 0; i < k; ++i) {
                f[i] = feats[size_t(i)].image->getchannel(x, y, 0, feats[size_t(i)].channel);
                if (feats[size_t(i)].image == frame.guides.depth)
                    f[i] = depth_scale * std::log(std::max(f[i], 1e-6f));
            }
            float* out = static_cast<float*>(source.pixeladdr(x, y));
            int o      = 0;
            for (int c = 0; c < nb; ++c)
                out[o++] = px[size_t(c)];
            for (int i = 0; i < k; ++i)
                out[o++] = f[i];
            for (int i = 0; i < k; ++i)
                for (int j = i; j < k; ++j)
                    out[o++] = f[i] * f[j];
            for (int c = 0; c < nc; ++c)
                for (int i = 0; i < k; ++i)
                    out[o++] = px[size_t(c)] * f[i];
        }
    });
    ImageBuf moments;
    ROI moment_roi    = roi;
    moment_roi.chbegin = 0;
    moment_roi.chend   = nm;
    if (!nlmeans(moments, source, frame.guides, int(env_float("MCD_FR_R", 5)), denoise_patch_radius,
                 frame.strength * env_float("MCD_FR_K", 1.0f),
                 { denoise_feature_sigmas.albedo * env_float("MCD_FR_SA", 1.0f),
                   denoise_feature_sigmas.normal * env_float("MCD_FR_SN", 1.0f),
                   denoise_feature_sigmas.depth * env_float("MCD_FR_SD", 1.0f) },
                 moment_roi, nthreads)) {
        dst.errorfmt("denoise: {}", moments.geterror());
        return false;
    }
    const float lambda = env_float("MCD_FR_LAMBDA", 1e-3f);
    ImageBuf out;
    std::vector<int> order(static_cast<size_t>(nb));
    for (int c = 0; c < nb; ++c)
        order[size_t(c)] = c;
    if (!OIIO::ImageBufAlgo::channels(out, moments, nb, order.data())) {
        dst.errorfmt("denoise: {}", out.geterror());
        return false;
    }
    parallel_rows(roi, nthreads, [&](int y) {
        std::array<double, max_features * max_features> a;
        std::array<double, max_features> mean_f, fp, b;
        for (int x = roi.xbegin; x < roi.xend; ++x) {
            const float* m = static_cast<const float*>(moments.pixeladdr(x, y));
            float* o       = static_cast<float*>(out.pixeladdr(x, y));
            for (int i = 0; i < k; ++i) {
                mean_f[size_t(i)] = m[nb + i];
                fp[size_t(i)] = feats[size_t(i)].image->getchannel(x, y, 0, feats[size_t(i)].channel);
                if (feats[size_t(i)].image == frame.guides.depth)
                    fp[size_t(i)] = depth_scale * std::log(std::max(float(fp[size_t(i)]), 1e-6f));
            }
            int p = nb + k;
            for (int i = 0; i < k; ++i)
                for (int j = i; j < k; ++j, ++p) {
                    const double cov = m[p] - mean_f[size_t(i)] * mean_f[size_t(j)];
                    a[size_t(i * k + j)] = a[size_t(j * k + i)] = cov + (i == j ? lambda : 0.0);
                }
            // Cholesky in place (lower).
            bool ok = true;
            for (int j = 0; j < k && ok; ++j) {
                double s = a[size_t(j * k + j)];
                for (int q = 0; q < j; ++q)
                    s -= a[size_t(j * k + q)] * a[size_t(j * k + q)];
                if (!(s > 0.0)) {
                    ok = false;
                    break;
                }
                a[size_t(j * k + j)] = std::sqrt(s);
                for (int i = j + 1; i < k; ++i) {
                    double t = a[size_t(i * k + j)];
                    for (int q = 0; q < j; ++q)
                        t -= a[size_t(i * k + q)] * a[size_t(j * k + q)];
                    a[size_t(i * k + j)] = t / a[size_t(j * k + j)];
                }
            }
            if (!ok)
                continue;
            for (int c = 0; c < nc; ++c) {
                const float* cf = m + nb + k + npairs + c * k;
                for (int i = 0; i < k; ++i) {
                    double t = cf[i] - double(m[c]) * mean_f[size_t(i)];
                    for (int q = 0; q < i; ++q)
                        t -= a[size_t(i * k + q)] * b[size_t(q)];
                    b[size_t(i)] = t / a[size_t(i * k + i)];
                }
                for (int i = k - 1; i >= 0; --i) {
                    double t = b[size_t(i)];
                    for (int q = i + 1; q < k; ++q)
                        t -= a[size_t(q * k + i)] * b[size_t(q)];
                    b[size_t(i)] = t / a[size_t(i * k + i)];
                }
                double v = m[c];
                for (int i = 0; i < k; ++i)
                    v += b[size_t(i)] * (fp[size_t(i)] - mean_f[size_t(i)]);
                o[c] = float(v);
            }
        }
    });
    return OIIO::ImageBufAlgo::copy(dst, out, OIIO::TypeUnknown, roi, nthreads)
           || (dst.errorfmt("denoise: {}", dst.geterror()), false);
}

}  // namespace mcdenoise
