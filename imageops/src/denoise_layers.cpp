// denoise_layers.cpp: denoise of a beauty with its light layers: stack the
// layers after the beauty's channels, denoise the stack once, split it.
#include <mcdenoise/denoise_layers.h>

#include "guides.h"
#include "layer_channels.h"
#include "operation.h"

#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
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

/// Channels of `src` over its overlap with `window` into the float image
/// `into` (data window `window`), from channel `chbegin` on.
bool put_channels(const ImageBuf& src, const ROI& window, int chbegin, ImageBuf& into)
{
    ROI from = OIIO::roi_intersection(src.roi(), window);
    if (!from.defined() || from.npixels() == 0)
        return true;
    from.chbegin = 0;
    from.chend   = src.nchannels();
    return src.get_pixels(from, OIIO::TypeDesc::FLOAT, into.pixeladdr(from.xbegin, from.ybegin, 0, chbegin),
                          into.pixel_stride(), into.scanline_stride());
}

/// The beauty's channels, then each layer's, as float over the beauty's
/// data window; layer pixels outside their own data window are 0.
bool stack(ImageBuf& dst, const ImageBuf& beauty, const std::vector<const ImageBuf*>& layers,
           ImageBuf& stacked)
{
    OIIO::ImageSpec spec = beauty.spec();
    spec.set_format(OIIO::TypeDesc::FLOAT);
    spec.channelformats.clear();
    for (const ImageBuf* layer : layers)
        for (const std::string& name : layer->spec().channelnames)
            spec.channelnames.push_back(name);
    spec.nchannels = int(spec.channelnames.size());
    // zeros only where some layer does not cover the beauty's data window
    const bool covered = std::all_of(layers.begin(), layers.end(), [&](const ImageBuf* layer) {
        const ROI l = layer->roi(), b = beauty.roi();
        return l.xbegin <= b.xbegin && l.xend >= b.xend && l.ybegin <= b.ybegin && l.yend >= b.yend;
    });
    stacked.reset(spec, covered ? OIIO::InitializePixels::No : OIIO::InitializePixels::Yes);
    bool ok     = put_channels(beauty, beauty.roi(), 0, stacked);
    int chbegin = beauty.nchannels();
    for (const ImageBuf* layer : layers) {
        ok = ok && put_channels(*layer, beauty.roi(), chbegin, stacked);
        chbegin += layer->nchannels();
    }
    if (!ok)
        dst.errorfmt("{}: stacking the layers: {}", op_name, stacked.geterror());
    return ok;
}

/// Channels [chbegin, chbegin + n) of `stacked` into `out` (allocated like
/// `like`, with its channel names, if uninitialized), over `roi`'s pixels.
bool split(ImageBuf& dst, const ImageBuf& stacked, int chbegin, const ImageBuf& like,
           const ROI& roi, int nthreads, ImageBuf& out)
{
    const int n          = like.nchannels();
    OIIO::ImageSpec spec = stacked.spec();
    spec.nchannels       = n;
    spec.channelnames    = like.spec().channelnames;
    spec.alpha_channel   = like.spec().alpha_channel;
    spec.z_channel       = -1;
    ImageBuf part(spec, OIIO::InitializePixels::No);
    ROI from    = roi;
    from.chbegin = chbegin;
    from.chend   = chbegin + n;
    ROI pixels   = roi;
    pixels.chbegin = 0;
    pixels.chend   = n;
    const bool ok = stacked.get_pixels(from, OIIO::TypeDesc::FLOAT, part.localpixels())
                    && (out.initialized()
                            ? OIIO::ImageBufAlgo::copy(out, part, OIIO::TypeDesc::UNKNOWN, pixels,
                                                       nthreads)
                            : (out = std::move(part), true));
    if (!ok)
        dst.errorfmt("{}: splitting the result: {}{}", op_name, stacked.geterror(),
                     out.geterror());
    return ok;
}

}  // namespace

bool denoise_layers(ImageBuf& dst, std::vector<ImageBuf>& dst_layers, const ImageBuf& beauty,
                    const std::vector<const ImageBuf*>& layers, const Guides& guides, ROI roi,
                    int nthreads)
{
    if (!resolve_roi(op_name, dst, beauty, roi) || !check_layers(dst, layers, roi))
        return false;
    ImageBuf stacked, result;
    if (!stack(dst, beauty, layers, stacked))
        return false;
    roi.chbegin = 0;
    roi.chend   = stacked.nchannels();
    if (!denoise_stacked(result, stacked, beauty.nchannels(), guides, roi, nthreads)) {
        dst.errorfmt("{}", result.geterror());
        return false;
    }
    dst_layers.resize(layers.size());
    if (!split(dst, result, 0, beauty, roi, nthreads, dst))
        return false;
    int chbegin = beauty.nchannels();
    for (size_t i = 0; i < layers.size(); ++i) {
        if (!split(dst, result, chbegin, *layers[i], roi, nthreads, dst_layers[i]))
            return false;
        chbegin += layers[i]->nchannels();
    }
    return true;
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
