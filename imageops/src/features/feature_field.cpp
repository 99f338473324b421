// feature_field.cpp: guide checks, the feature weight's planes, the colour
// and luminance of a pixel, and the per-pixel variance, for the
// feature-guided filters.
#include "features/feature_field.h"

#include "core/window.h"
#include "features/weighted_sums.h"
#include "walkers/window_variance.h"

#include <algorithm>
#include <cmath>

namespace mcdenoise {

using OIIO::ImageBuf;
using OIIO::ROI;
using OIIO::roi_union;

namespace {

// features.h's depth rule: the log of a finite depth in (0, 1e9), else of
// 1e9 ("infinitely far"). `load_depths` has already mapped far depths to
// +inf.
float log_depth(float d)
{
    static const double far = std::log(double(infinitely_far));
    return float(std::isfinite(d) && d > 0.0f ? std::log(double(d)) : far);
}

// The factor that turns a feature into a plane whose squared differences
// are the exponent's term |f_p - f_q|^2 / (2 sigma^2).
float feature_scale(float sigma)
{
    return float(1.0 / (double(sigma) * std::sqrt(2.0)));
}

}  // namespace

bool check_colour_guide(const char* op, const char* name, ImageBuf& dst, const ImageBuf& guide,
                        const ROI& roi)
{
    const int nc = guide.initialized() ? guide.nchannels() : feature_colour_channels;
    if (nc != 1 && nc != feature_colour_channels) {
        dst.errorfmt("{}: {} has {} channels, expected 3 or 1", op, name, nc);
        return false;
    }
    return check_guide(op, name, dst, guide, nc, roi);
}

bool check_feature_guides(const char* op, ImageBuf& dst, const Guides& guides, const ROI& roi)
{
    return (!guides.object_id || check_guide(op, "object_id", dst, *guides.object_id, 1, roi))
           && (!guides.normal || check_guide(op, "normal", dst, *guides.normal, 3, roi))
           && (!guides.depth || check_guide(op, "depth", dst, *guides.depth, 1, roi))
           && (!guides.albedo || check_colour_guide(op, "albedo", dst, *guides.albedo, roi))
           && (!guides.variance
               || check_colour_guide(op, "variance", dst, *guides.variance, roi));
}

bool load_guide_channels(const char* op, ImageBuf& dst, const ImageBuf& guide,
                         const ROI& region, int nthreads, GuideChannels& out)
{
    const ROI dw = guide.roi();
    ROI inside   = OIIO::roi_intersection(region, dw);
    inside.chbegin = 0;
    inside.chend   = guide.nchannels();
    out            = GuideChannels(region, guide.nchannels(), 0.0f);
    if (!inside.defined() || inside.npixels() == 0)
        return true;
    PixelBlock block;
    if (!load_block(guide, inside, block)) {
        dst.errorfmt("{}: could not read a guide: {}", op, guide.geterror());
        return false;
    }
    const int nc = block.nchannels;
    parallel_rows(inside, nthreads, [&](int y) {
        const float* in = block.row(y);
        const size_t at = out.offset(inside.xbegin, y);
        for (int i = 0; i < inside.width(); ++i, in += nc)
            for (int c = 0; c < nc; ++c)
                out.values[size_t(c)][at + i] = std::isfinite(in[c]) ? in[c] : 0.0f;
    });
    return true;
}

void FeatureField::weights_row(int y, int x0, int n, int dx, int dy, const float* e,
                               float scale, float* w) const
{
    weights_row(y, x0, n, dx, dy, e, scale, w, *this);
}

void FeatureField::weights_row(int y, int x0, int n, int dx, int dy, const float* e,
                               float scale, float* w, const FeatureField& other) const
{
    using OIIO::simd::vfloat8;
    const size_t pc = dims.offset(x0, y), pq = other.dims.offset(x0 + dx, y + dy);
    const vfloat8 s(scale);
    const bool by_id = !ids.values.empty();
    const Id* ka     = by_id ? ids.values.data() + pc : nullptr;
    const Id* kb     = by_id ? other.ids.values.data() + pq : nullptr;
    for_each_lane_block(n, w, [&](int, auto&& load) {
        vfloat8 x = load(e);
        for (size_t k = 0; k < dims.values.size(); ++k) {
            const vfloat8 t = load(dims.values[k].data() + pc)
                              - load(other.dims.values[k].data() + pq);
            x = x + t * t;
        }
        const vfloat8 v = weight_lanes(x, s);
        return by_id ? OIIO::simd::select(load(ka) == load(kb), v, vfloat8(0.0f)) : v;
    });
}

bool load_feature_field(const char* op, ImageBuf& dst, const Guides& guides,
                        const FeatureSigmas& sigmas, const ROI& region, int nthreads,
                        FeatureField& field)
{
    field.dims = Planes<float>(region, 0);
    field.ids  = IdPlane();
    if (guides.object_id
        && !load_object_ids(op, dst, *guides.object_id, region, nthreads, field.ids))
        return false;
    if (guides.albedo && sigmas.albedo > 0.0f) {
        GuideChannels albedo;
        if (!load_guide_channels(op, dst, *guides.albedo, region, nthreads, albedo))
            return false;
        const float s = feature_scale(sigmas.albedo);
        for (LargeVector<float>& plane : albedo.values) {
            for (float& v : plane)
                v *= s;
            field.dims.values.push_back(std::move(plane));
        }
    }
    if (guides.normal && sigmas.normal > 0.0f) {
        NormalPlanes normals;
        if (!load_normals(op, dst, *guides.normal, region, nthreads, normals))
            return false;
        const float s = feature_scale(sigmas.normal);
        for (LargeVector<float>& plane : normals.components.values) {
            for (float& v : plane)
                v *= s;
            field.dims.values.push_back(std::move(plane));
        }
    }
    if (guides.depth && sigmas.depth > 0.0f) {
        Plane<float> depths;
        if (!load_depths(op, dst, *guides.depth, region, nthreads, depths))
            return false;
        const float s = feature_scale(sigmas.depth);
        for_each_pixel(region, nthreads, [&](int, int, size_t i) {
            depths.values[i] = log_depth(depths.values[i]) * s;
        });
        field.dims.values.push_back(std::move(depths.values));
    }
    return true;
}

std::array<float, feature_colour_channels> luminance_weights(int nc)
{
    if (nc == feature_colour_channels)
        return { 0.2126f, 0.7152f, 0.0722f };  // Rec. 709 luma
    std::array<float, feature_colour_channels> mean {};
    for (int c = 0; c < nc; ++c)
        mean[size_t(c)] = 1.0f / float(nc);
    return mean;
}

ColourField colour_field(const PixelBlock& block, const ROI& region, int nthreads)
{
    const int nc  = colour_channels(block.nchannels);
    const auto lw = luminance_weights(nc);
    ColourField field { Planes<float>(region, nc), Plane<float>(region) };
    for_each_pixel(region, nthreads, [&](int x, int y, size_t i) {
        const float* v = block.pixel(x, y);
        float lum      = 0.0f;
        for (int c = 0; c < nc; ++c) {
            const float u = std::isfinite(v[c]) ? v[c] : 0.0f;
            field.colour.values[size_t(c)][i] = u;
            lum += lw[size_t(c)] * u;
        }
        field.luminance.values[i] = lum;
    });
    return field;
}

bool load_variance(const char* op, ImageBuf& dst, const ImageBuf* variance,
                   const ColourField& colour, const ROI& region, const ROI& data_window,
                   int nthreads, VarianceField& out)
{
    const int nc  = colour.nchannels();
    const auto lw = luminance_weights(nc);
    out           = VarianceField { Planes<float>(region, nc), Plane<float>(region) };
    if (!variance) {
        for (int c = 0; c < nc; ++c)
            window_variances(colour.colour.values[size_t(c)].data(), colour.colour.region, region,
                             data_window, nthreads, out.colour.values[size_t(c)].data());
        window_variances(colour.luminance.values.data(), colour.luminance.region, region,
                         data_window, nthreads, out.luminance.values.data());
        return true;
    }
    GuideChannels given;
    if (!load_guide_channels(op, dst, *variance, region, nthreads, given))
        return false;
    for_each_pixel(region, nthreads, [&](int, int, size_t i) {
        float lum = 0.0f;
        for (int c = 0; c < nc; ++c) {
            const int k   = std::min(c, given.nchannels() - 1);
            const float v = std::max(0.0f, given.values[size_t(k)][i]);
            out.colour.values[size_t(c)][i] = v;
            lum += lw[size_t(c)] * lw[size_t(c)] * v;
        }
        out.luminance.values[i] = lum;
    });
    return true;
}

bool load_feature_inputs(const char* op, ImageBuf& dst, const ImageBuf& beauty,
                         const Guides& guides, const FeatureSigmas& sigmas, const ROI& window,
                         const ROI& variance_region, int nthreads, FeatureInputs& in)
{
    const ROI dw = beauty.roi();
    ROI read     = grow_and_clip(roi_union(window, variance_region), 1, dw);
    read.chbegin = 0;
    read.chend   = beauty.nchannels();
    PixelBlock block;
    if (!read_beauty(op, dst, beauty, read, block)
        || !load_feature_field(op, dst, guides, sigmas, window, nthreads, in.features))
        return false;
    in.colour = colour_field(block, read, nthreads);
    if (!load_variance(op, dst, guides.variance, in.colour, variance_region, dw, nthreads,
                       in.variance))
        return false;
    in.values = sum_source(block, 0, beauty.nchannels(), window, nthreads);
    return true;
}

}  // namespace mcdenoise
