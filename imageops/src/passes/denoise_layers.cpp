// denoise_layers.cpp: denoise of a beauty with its light layers: the
// beauty's steps of `denoise`, each decision (the outlier split, the
// NL-means weights, the factor the excess is given back with) made once on
// the beauty and applied to every layer's planes alongside; then each layer
// backed off where those weights blurred it, and the layers made to add up
// to the denoised beauty again.
#include <mcdenoise/denoise_layers.h>
#include <mcdenoise/denoise.h>

#include "core/guides.h"
#include "core/operation.h"
#include "core/window.h"
#include "denoise/denoise_frame.h"
#include "denoise/energy_outliers.h"
#include "features/nlmeans_layers.h"
#include "passes/layer_backoff.h"
#include "passes/layer_steps.h"
#include "passes/layer_sums.h"

#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <map>
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

/// Check `terms`: none, or one per layer, each colour readable and
/// covering `roi` with the layer's colour channels.
bool check_terms(ImageBuf& dst, const std::vector<const ImageBuf*>& layers,
                 const std::vector<LayerTerm>& terms, const ROI& roi)
{
    if (!terms.empty() && terms.size() != layers.size()) {
        dst.errorfmt("{}: {} layer terms for {} layers", op_name, terms.size(), layers.size());
        return false;
    }
    for (size_t i = 0; i < terms.size(); ++i) {
        const std::string name = "the colour of layer " + std::to_string(i);
        if (terms[i].colour
            && !check_guide(op_name, name.c_str(), dst, *terms[i].colour,
                            std::min(3, layers[i]->nchannels()), roi))
            return false;
    }
    return true;
}

/// `image` (a float image over a region holding `roi`) over `roi` only:
/// moved, pixels and all, when it covers no more.
ImageBuf within(ImageBuf&& image, const ROI& roi, int nthreads)
{
    if (image.roi().xbegin == roi.xbegin && image.roi().xend == roi.xend
        && image.roi().ybegin == roi.ybegin && image.roi().yend == roi.yend)
        return std::move(image);
    ROI pixels    = roi;
    pixels.chbegin = 0;
    pixels.chend   = image.nchannels();
    return OIIO::ImageBufAlgo::crop(image, pixels, nthreads);
}

/// A layer's result over the ROI, the layer as rendered over the ROI grown
/// by `backoff_reach`, and the result's estimated error variance.
struct LayerResult {
    ImageBuf image;
    PixelBlock raw;
    Plane<float> error;
};

/// `layer`'s average (over the ROI grown by `backoff_reach`) backed off
/// towards its kept values (`back_off_layer`) into `result`, over `roi`.
bool back_off(ImageBuf& dst, const ImageBuf& layer, ImageBuf average, const Plane<float>& scale,
              const ROI& roi, int nthreads, BackoffPlanes& planes, LayerResult& result)
{
    ROI read     = average.roi();
    read.chbegin = 0;
    read.chend   = layer.nchannels();
    PixelBlock averaged;
    if (!load_block(layer, read, result.raw) || !load_block(average, read, averaged)) {
        dst.errorfmt("{}: could not read a layer: {}", op_name,
                     layer.has_error() ? layer.geterror() : average.geterror());
        return false;
    }
    // `averaged` views the average's pixels, which a move keeps in place.
    result.image = within(std::move(average), roi, nthreads);
    back_off_layer(result.image, averaged, result.raw, scale, nthreads, planes, result.error);
    return true;
}

/// The results of each rebuild of `terms` (every layer in one plain sum
/// when empty) corrected to add up to the denoised beauty `out`
/// (`reconcile_sum`) where the raw layers rebuild the raw `beauty`.
bool add_up(ImageBuf& dst, const ImageBuf& out, const ImageBuf& beauty,
            const std::vector<LayerTerm>& terms, const ROI& roi, int nthreads,
            std::vector<LayerResult>& results)
{
    ROI colour     = roi;
    colour.chbegin = 0;
    colour.chend   = colour_channels(beauty.nchannels());
    PixelBlock raw;
    std::vector<PixelBlock> colours(results.size());
    if (!load_block(beauty, colour, raw)) {
        dst.errorfmt("{}: could not read the beauty: {}", op_name, beauty.geterror());
        return false;
    }
    std::map<int, std::vector<SumTerm>> sums;
    for (size_t i = 0; i < results.size(); ++i) {
        const LayerTerm term = terms.empty() ? LayerTerm {} : terms[i];
        if (term.sum < 0)
            continue;
        colour.chend = std::min(3, results[i].image.nchannels());
        if (term.colour && !load_block(*term.colour, colour, colours[i])) {
            dst.errorfmt("{}: could not read the colour of layer {}: {}", op_name, i,
                         term.colour->geterror());
            return false;
        }
        sums[term.sum].push_back({ &results[i].image, &results[i].raw,
                                   term.colour ? &colours[i] : nullptr, &results[i].error });
    }
    for (const auto& sum : sums)
        reconcile_sum(out, raw, sum.second, nthreads);
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

bool denoise_layers_steps(LayerSteps steps, ImageBuf& dst, std::vector<ImageBuf>& dst_layers,
                          const ImageBuf& beauty, const std::vector<const ImageBuf*>& layers,
                          const Guides& guides, const std::vector<LayerTerm>& terms, ROI roi,
                          int nthreads)
{
    const bool own_noise = steps == LayerSteps::all;
    if (!resolve_roi(op_name, dst, beauty, roi) || !check_layers(dst, layers, roi)
        || !check_terms(dst, layers, terms, roi)
        || !check_denoise_guides(op_name, dst, beauty, guides, roi))
        return false;
    const ROI region = denoise_region(beauty, roi);
    // The back-off reads windows around the ROI's pixels: the average is
    // taken over `grown`, so the result does not depend on the ROI.
    const ROI grown = grow_and_clip(roi, backoff_reach, beauty.roi());
    DenoiseFrame frame;
    SplitScales scales;
    std::vector<SumSource> values;
    std::vector<Planes<float>> excess;
    if (!prepare_denoise_frame(dst, beauty, guides, region, nthreads, frame, &scales)
        || !split_layers(dst, layers, scales, region, grown, nthreads, values, excess))
        return false;
    ExcessWeights weights = firefly_sources(frame, roi, beauty.roi());
    const WeightTap tap   = weight_tap(weights, grown);
    // Into new images, so the excess can be added to float pixels in place.
    ImageBuf out;
    std::vector<ImageBuf> averages;
    if (!nlmeans_layers(out, averages, frame.clamped, layers, std::move(values), frame.guides,
                        denoise_search_radius, denoise_patch_radius, frame.strength,
                        denoise_feature_sigmas, grown, nthreads, &tap)) {
        dst.errorfmt("{}", out.geterror());
        return false;
    }
    out = within(std::move(out), roi, nthreads);
    if (!finish_firefly_weights(dst, frame, grown, beauty.roi(), nthreads, weights))
        return false;
    Plane<float> factors;
    if (!give_back_excess(op_name, out, weights, frame.excess, roi,
                          premultiplied_alpha(beauty), nthreads, &factors)) {
        dst.errorfmt("{}", out.geterror());
        return false;
    }
    out.specmod().attribute("mcdenoise:denoise_guides", denoise_guide_names(guides));
    std::vector<LayerResult> results(layers.size());
    BackoffPlanes planes;
    for (size_t i = 0; i < layers.size(); ++i) {
        if (own_noise
            && !back_off(dst, *layers[i], std::move(averages[i]), scales.scale, roi, nthreads,
                         planes, results[i]))
            return false;
        if (!own_noise)
            results[i].image = within(std::move(averages[i]), roi, nthreads);
        give_back_layer_excess(results[i].image, weights, excess[i], roi, factors, nthreads);
    }
    if (own_noise && !add_up(dst, out, beauty, terms, roi, nthreads, results))
        return false;
    dst_layers.resize(layers.size());
    for (size_t i = 0; i < layers.size(); ++i)
        if (!put_result(dst, results[i].image, roi, nthreads, dst_layers[i]))
            return false;
    return put_result(dst, out, roi, nthreads, dst);
}


bool denoise_layers(ImageBuf& dst, std::vector<ImageBuf>& dst_layers, const ImageBuf& beauty,
                    const std::vector<const ImageBuf*>& layers, const Guides& guides,
                    const std::vector<LayerTerm>& terms, ROI roi, int nthreads)
{
    return denoise_layers_steps(LayerSteps::all, dst, dst_layers, beauty, layers, guides, terms,
                                roi, nthreads);
}

std::vector<ImageBuf> denoise_layers(const ImageBuf& beauty,
                                     const std::vector<const ImageBuf*>& layers,
                                     const Guides& guides, const std::vector<LayerTerm>& terms,
                                     ROI roi, int nthreads)
{
    std::vector<ImageBuf> out(1);
    std::vector<ImageBuf> dst_layers;
    if (!denoise_layers(out[0], dst_layers, beauty, layers, guides, terms, roi, nthreads)) {
        if (!out[0].has_error())
            out[0].errorfmt("mcdenoise: operation failed");
        return out;
    }
    for (ImageBuf& layer : dst_layers)
        out.push_back(std::move(layer));
    return out;
}

}  // namespace mcdenoise
