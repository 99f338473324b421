// denoise_layers.cpp: denoise of a beauty with its light layers: the
// beauty's steps of `denoise`, each decision (the outlier split, the
// NL-means weights, the factor the excess is given back with) made once on
// the beauty and applied to every layer's planes alongside.
#include <mcdenoise/denoise_layers.h>
#include <mcdenoise/denoise.h>

#include "denoise_frame.h"
#include "energy_outliers.h"
#include "guides.h"
#include "layer_channels.h"
#include "operation.h"
#include "window.h"

#include <OpenImageIO/imagebufalgo.h>

#include <string>

namespace mcdenoise {

using OIIO::ImageBuf;
using OIIO::ROI;

namespace {

constexpr const char* op_name = "denoise_layers";

/// Check every layer: readable, flat, covering `roi`.
bool check_layers(ImageBuf& dst, const std::vector<const ImageBuf*>& layers, const ROI& roi)
{
    for (size_t i = 0; i < layers.size(); ++i) {
        const std::string name = "layer " + std::to_string(i);
        if (!layers[i]) {
            dst.errorfmt("{}: {} is null", op_name, name);
            return false;
        }
        if (layers[i]->initialized() && (layers[i]->deep() || layers[i]->spec().depth > 1)) {
            dst.errorfmt("{}: {} is a deep or volume image", op_name, name);
            return false;
        }
        if (!check_guide(op_name, name.c_str(), dst, *layers[i], layers[i]->nchannels(), roi))
            return false;
    }
    return true;
}

/// What `denoise` does to the beauty, done to each layer: the outlier
/// split of `scales` (over `region`), into `values[i]` over the search
/// region of the beauty's `roi` and `excess[i]` over `region`.
bool split_layers(ImageBuf& dst, const std::vector<const ImageBuf*>& layers,
                  const SplitScales& scales, const ROI& region, const ROI& roi, int nthreads,
                  std::vector<SumSource>& values, std::vector<Planes<float>>& excess)
{
    const ROI search = grow_and_clip(roi, denoise_search_radius, region);
    values.resize(layers.size());
    excess.resize(layers.size());
    for (size_t i = 0; i < layers.size(); ++i) {
        ROI read     = region;
        read.chbegin = 0;
        read.chend   = layers[i]->nchannels();
        PixelBlock block;
        if (!load_block(*layers[i], read, block)) {
            dst.errorfmt("{}: could not read layer {}: {}", op_name, i, layers[i]->geterror());
            return false;
        }
        split_layer(block, scales, search, nthreads, values[i], excess[i]);
    }
    return true;
}

/// `from` (a float image over `roi`) into `out`: moved when `out` is
/// uninitialized, else copied into its pixels.
bool put_result(ImageBuf& dst, ImageBuf& from, const ROI& roi, int nthreads, ImageBuf& out)
{
    if (!out.initialized()) {
        out = std::move(from);
        return true;
    }
    ROI pixels    = roi;
    pixels.chbegin = 0;
    pixels.chend   = from.nchannels();
    if (OIIO::ImageBufAlgo::copy(out, from, OIIO::TypeDesc::UNKNOWN, pixels, nthreads))
        return true;
    dst.errorfmt("{}: writing the result: {}", op_name, out.geterror());
    return false;
}

}  // namespace

bool denoise_layers(ImageBuf& dst, std::vector<ImageBuf>& dst_layers, const ImageBuf& beauty,
                    const std::vector<const ImageBuf*>& layers, const Guides& guides, ROI roi,
                    int nthreads)
{
    if (!resolve_roi(op_name, dst, beauty, roi) || !check_layers(dst, layers, roi)
        || !check_denoise_guides(op_name, dst, beauty, guides, roi))
        return false;
    const ROI region = denoise_region(beauty, roi);
    DenoiseFrame frame;
    SplitScales scales;
    std::vector<SumSource> values;
    std::vector<Planes<float>> excess;
    if (!prepare_denoise_frame(dst, beauty, guides, region, nthreads, frame, &scales)
        || !split_layers(dst, layers, scales, region, roi, nthreads, values, excess))
        return false;
    ExcessWeights weights = firefly_sources(frame, roi, beauty.roi());
    const WeightTap tap   = weight_tap(weights, roi);
    // Into new images, so the excess can be added to float pixels in place.
    ImageBuf out;
    std::vector<ImageBuf> outs;
    if (!nlmeans_layers(out, outs, frame.clamped, layers, std::move(values), frame.guides,
                        denoise_search_radius, denoise_patch_radius, frame.strength,
                        denoise_feature_sigmas, roi, nthreads, &tap)) {
        dst.errorfmt("{}", out.geterror());
        return false;
    }
    if (!finish_firefly_weights(dst, frame, roi, beauty.roi(), nthreads, weights))
        return false;
    Plane<float> factors;
    if (!give_back_excess(op_name, out, weights, frame.excess, roi,
                          premultiplied_alpha(beauty), nthreads, &factors)) {
        dst.errorfmt("{}", out.geterror());
        return false;
    }
    out.specmod().attribute("mcdenoise:denoise_guides", denoise_guide_names(guides));
    dst_layers.resize(layers.size());
    for (size_t i = 0; i < layers.size(); ++i) {
        give_back_layer_excess(outs[i], weights, excess[i], roi, factors, nthreads);
        if (!put_result(dst, outs[i], roi, nthreads, dst_layers[i]))
            return false;
    }
    return put_result(dst, out, roi, nthreads, dst);
}

std::vector<ImageBuf> denoise_layers(const ImageBuf& beauty,
                                     const std::vector<const ImageBuf*>& layers,
                                     const Guides& guides, ROI roi, int nthreads)
{
    std::vector<ImageBuf> out(1);
    std::vector<ImageBuf> dst_layers;
    if (!denoise_layers(out[0], dst_layers, beauty, layers, guides, roi, nthreads)) {
        if (!out[0].has_error())
            out[0].errorfmt("mcdenoise: operation failed");
        return out;
    }
    for (ImageBuf& layer : dst_layers)
        out.push_back(std::move(layer));
    return out;
}

}  // namespace mcdenoise
