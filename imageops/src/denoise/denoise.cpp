// denoise.cpp: the one-call denoiser, a fixed chain of this library's
// filters whose strength follows from the guides it is given.
#include <mcdenoise/denoise.h>
#include <mcdenoise/nlmeans.h>

#include "core/operation.h"
#include "core/window.h"
#include "denoise/denoise_frame.h"
#include "denoise/energy_outliers.h"
#include "features/feature_field.h"
#include "features/nlmeans_frames.h"
#include "features/nlmeans_layers.h"
#include "walkers/window_variance.h"

#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <string>
#include <vector>

namespace mcdenoise {

using OIIO::ImageBuf;
using OIIO::ROI;

namespace {

constexpr const char* op_name     = "denoise";
constexpr float firefly_factor    = 2.0f;
constexpr int firefly_radius      = 2;

/// The variance of the full estimate from two independent halves, over
/// `region`: per colour channel, `pixel` = (half_a - half_b)^2 / 4 and its
/// 3x3 mean `smooth`.
bool variance_from_halves(ImageBuf& dst, const Guides& guides, const ROI& region,
                          int nthreads, ImageBuf& pixel, ImageBuf& smooth)
{
    if (!OIIO::ImageBufAlgo::sub(pixel, *guides.half_a, *guides.half_b, region, nthreads)
        || !OIIO::ImageBufAlgo::mul(pixel, pixel, pixel, region, nthreads)
        || !OIIO::ImageBufAlgo::mul(pixel, pixel, 0.25f, region, nthreads)
        || !mean(smooth, pixel, 3, region, nthreads)) {
        dst.errorfmt("{}: variance from half_a, half_b: {}", op_name,
                     smooth.has_error() ? smooth.geterror() : pixel.geterror());
        return false;
    }
    return true;
}

/// The variance when neither the variance guide nor the halves are given:
/// per colour channel, the smallest 3x3 sample variance among the 3x3
/// windows around the pixel, over `region` (the data window of `clamped`).
/// A window across an edge counts the edge as noise; the smallest window
/// nearby lies on one side of it.
bool estimated_variance(ImageBuf& dst, const ImageBuf& clamped, const ROI& region, int nthreads,
                        ImageBuf& variance)
{
    PixelBlock block;
    VarianceField sample;
    ROI colour_roi  = region;
    colour_roi.chend = colour_channels(clamped.nchannels());
    if (!read_beauty(op_name, dst, clamped, colour_roi, block))
        return false;
    const ColourField colour = colour_field(block, colour_roi, nthreads);
    if (!load_variance(op_name, dst, nullptr, colour, colour_roi, region, nthreads, sample))
        return false;
    const int nc = colour.nchannels();
    Planes<float> smallest(sample.colour.region, nc);
    for (int c = 0; c < nc; ++c)
        smallest_in_windows(sample.colour.values[size_t(c)].data(), sample.colour.region,
                            nthreads, smallest.values[size_t(c)].data());
    variance.reset(OIIO::ImageSpec(colour_roi, OIIO::TypeDesc::FLOAT));
    parallel_rows(region, nthreads, [&](int y) {
        for (int x = region.xbegin; x < region.xend; ++x) {
            float* out = static_cast<float*>(variance.pixeladdr(x, y));
            for (int c = 0; c < nc; ++c)
                out[c] = *smallest.from(c, x, y);
        }
    });
    return true;
}

/// Check the halves: both or neither, each with the beauty's colour
/// channels, covering `roi`.
bool check_halves(ImageBuf& dst, const ImageBuf& beauty, const Guides& guides, const ROI& roi)
{
    if (!guides.half_a && !guides.half_b)
        return true;
    if (!guides.half_a || !guides.half_b) {
        dst.errorfmt("{}: half_a and half_b go together; only {} was given", op_name,
                     guides.half_a ? "half_a" : "half_b");
        return false;
    }
    const int nc = colour_channels(beauty.nchannels());
    return check_guide(op_name, "half_a", dst, *guides.half_a, nc, roi)
           && check_guide(op_name, "half_b", dst, *guides.half_b, nc, roi);
}

}  // namespace

std::string denoise_guide_names(const Guides& guides)
{
    std::string names;
    for (const GuideField& field : guide_fields)
        if ((field.bit & denoise_guides) && guides.*field.member)
            names += (names.empty() ? "" : ",") + std::string(field.name);
    return names;
}

bool check_denoise_guides(const char* op, ImageBuf& dst, const ImageBuf& beauty,
                          const Guides& guides, const ROI& roi)
{
    Guides read    = guides;
    read.object_id = nullptr;
    return check_feature_guides(op, dst, read, roi) && check_halves(dst, beauty, guides, roi);
}

ROI denoise_region(const ImageBuf& beauty, const ROI& roi)
{
    // The sources that give excess to the ROI (within the Gaussian's reach,
    // or with their windows), their patches and the two 3x3 windows of an
    // estimated variance, so the result does not depend on the ROI.
    const int reach = std::max(excess_spread_radius,
                               2 * denoise_search_radius + denoise_patch_radius);
    ROI region      = grow_and_clip(roi, reach + 2, beauty.roi());
    region.chbegin = 0;
    region.chend   = beauty.nchannels();
    return region;
}

bool prepare_denoise_frame(ImageBuf& dst, const ImageBuf& beauty, const Guides& guides,
                           const ROI& region, int nthreads,
                           DenoiseFrame& frame, SplitScales* scales)
{
    frame.guides           = guides;  // the object id is not read (see denoise.h)
    frame.guides.object_id = nullptr;
    ROI colour   = region;
    colour.chend = colour_channels(beauty.nchannels());
    // The outlier test reads the noise of the pixel itself: a firefly in
    // one half shows in its own (a - b)^2 / 4, but a 3x3 mean dilutes it.
    ImageBuf pixel_variance;
    const ImageBuf* test_variance = guides.variance;
    if (!guides.variance && guides.half_a) {
        if (!variance_from_halves(dst, guides, colour, nthreads, pixel_variance, frame.variance))
            return false;
        frame.guides.variance = &frame.variance;
        test_variance         = &pixel_variance;
    }
    frame.outliers_measured = test_variance != nullptr;
    if (!split_outliers(op_name, dst, beauty, test_variance, firefly_factor,
                        firefly_radius, region, nthreads, frame.clamped, frame.excess,
                        scales))
        return false;
    const bool measured = frame.guides.variance != nullptr;
    if (!measured) {
        if (!estimated_variance(dst, frame.clamped, region, nthreads, frame.variance))
            return false;
        frame.guides.variance = &frame.variance;
    }
    frame.strength = measured ? denoise_measured_strength : denoise_estimated_strength;
    return true;
}

ExcessWeights firefly_sources(const DenoiseFrame& frame, const ROI& roi, const ROI& dw)
{
    if (frame.outliers_measured) {
        ExcessWeights wide;
        wide.wide        = true;
        wide.data_window = dw;
        return wide;
    }
    return excess_sources(frame.excess, grow_and_clip(roi, denoise_search_radius, dw),
                          denoise_search_radius);
}

NlmFrame own_window(const FeatureInputs& planes)
{
    return { &planes.colour,   &planes.variance, &planes.features, &planes.features,
             &planes.values,   nullptr,          denoise_search_radius, true };
}

bool finish_firefly_weights(ImageBuf& dst, const DenoiseFrame& frame, const ROI& roi,
                            const ROI& dw, int nthreads, ExcessWeights& weights)
{
    if (sources_outside(weights, roi)) {
        const ROI window = grow_and_clip(roi, 2 * denoise_search_radius, dw);
        FeatureInputs planes;
        if (!load_feature_inputs(op_name, dst, frame.clamped, frame.guides,
                                 denoise_feature_sigmas, window,
                                 grow_and_clip(window, denoise_patch_radius, dw), nthreads, planes))
            return false;
        fill_outside(weights, roi, own_window(planes), planes.colour, planes.variance, dw,
                     denoise_patch_radius, frame.strength, nthreads);
    }
    normalise_weights(weights);
    return true;
}

bool denoise(ImageBuf& dst, const ImageBuf& beauty, const Guides& guides, ROI roi, int nthreads)
{
    if (!resolve_roi(op_name, dst, beauty, roi)
        || !check_denoise_guides(op_name, dst, beauty, guides, roi))
        return false;
    DenoiseFrame frame;
    if (!prepare_denoise_frame(dst, beauty, guides, denoise_region(beauty, roi), nthreads, frame))
        return false;
    ExcessWeights weights = firefly_sources(frame, roi, beauty.roi());
    const WeightTap tap   = weight_tap(weights, roi);
    std::vector<ImageBuf> no_layers;
    if (!nlmeans_layers(dst, no_layers, frame.clamped, {}, {}, frame.guides,
                        denoise_search_radius, denoise_patch_radius, frame.strength,
                        denoise_feature_sigmas, roi, nthreads, &tap)
        || !finish_firefly_weights(dst, frame, roi, beauty.roi(), nthreads, weights))
        return false;
    if (!give_back_excess(op_name, dst, weights, frame.excess, roi,
                          premultiplied_alpha(beauty), nthreads))
        return false;
    dst.specmod().attribute("mcdenoise:denoise_guides", denoise_guide_names(guides));
    return true;
}

ImageBuf denoise(const ImageBuf& beauty, const Guides& guides, ROI roi, int nthreads)
{
    return value_form([&](ImageBuf& dst) { return denoise(dst, beauty, guides, roi, nthreads); });
}

}  // namespace mcdenoise
