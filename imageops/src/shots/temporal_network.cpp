// temporal_network.cpp: the network on a shot: each frame's network result
// accumulated with its matching neighbours' (shot_accumulation.h).
#include <mcdenoise/denoise_network.h>

#include "core/operation.h"
#include "shots/shot_accumulation.h"
#include "shots/temporal_frame.h"

#include <OpenImageIO/imagebufalgo.h>

namespace mcdenoise {

using OIIO::ImageBuf;
using OIIO::ROI;

namespace {

// The guides the network reads of a frame.
Guides network_guides(const FrameInput& frame)
{
    Guides g;
    g.albedo = frame.guides.albedo;
    g.normal = frame.guides.normal;
    return g;
}

// Each frame's network result, checked: made, over its frame's data
// window with its channels; else an error naming the frame (`what`).
const ImageBuf* denoised_of(ImageBuf& dst, const NetworkFrame& f, const PreparedFrameData& data,
                            const std::string& what)
{
    const ImageBuf* d = f.denoised.get();
    if (!f.error.empty())
        dst.errorfmt("{}: {}: {}", temporal_op, what, f.error);
    else if (!d)
        dst.errorfmt("{}: {}: no network result", temporal_op, what);
    else if (d->roi() != data.input.beauty->roi()
             || d->nchannels() != data.input.beauty->nchannels())
        dst.errorfmt("{}: {}: its network result does not cover its data window", temporal_op,
                     what);
    else
        return d;
    return nullptr;
}

// `from` (a float image over `roi`, every channel) into `dst`: moved when
// `dst` is uninitialized, else copied into its pixels; with `like`'s
// attributes of the network run.
bool put_result(ImageBuf& dst, ImageBuf&& from, const ImageBuf& like, const ROI& roi,
                int nthreads)
{
    for (const char* name : { "mcdenoise:denoise_guides", "mcdenoise:network" })
        if (const OIIO::ParamValue* p = like.spec().find_attribute(name))
            from.specmod().attribute(name, p->get_string());
    if (!dst.initialized()) {
        dst = std::move(from);
        return true;
    }
    if (OIIO::ImageBufAlgo::copy(dst, from, OIIO::TypeDesc::UNKNOWN, roi, nthreads))
        return true;
    dst.errorfmt("{}: writing the result: {}", temporal_op, dst.geterror());
    return false;
}

}  // namespace

NetworkFrame prepare_network_frame(const FrameInput& frame, const NetworkOptions& options,
                                   int nthreads)
{
    NetworkFrame out;
    out.prepared = prepare_frame(frame, nthreads);
    if (!out.prepared.data) {
        out.error = out.prepared.error;
        return out;
    }
    auto denoised = std::make_shared<ImageBuf>();
    if (!denoise_network(*denoised, *frame.beauty, network_guides(frame), options, {}, nthreads)) {
        out.error = denoised->geterror();
        return out;
    }
    out.denoised = std::move(denoised);
    return out;
}

bool denoise_network(ImageBuf& dst, const NetworkFrame& centre,
                     const std::vector<NetworkFrame>& neighbours, const std::vector<int>& offsets,
                     ROI roi, int nthreads)
{
    std::vector<PreparedFrame> prepared;
    for (const NetworkFrame& n : neighbours)
        prepared.push_back(n.prepared);
    const PreparedFrameData* c = nullptr;
    std::vector<const PreparedFrameData*> ns;
    if (!shot_data(dst, centre.prepared, prepared, offsets, c, ns))
        return false;
    std::vector<const ImageBuf*> images { denoised_of(dst, centre, *c, "centre frame") };
    for (size_t i = 0; images.back() && i < ns.size(); ++i)
        images.push_back(denoised_of(dst, neighbours[i], *ns[i],
                                     "neighbour frame at offset " + std::to_string(offsets[i])));
    if (!images.back() || !resolve_roi(temporal_op, dst, *c->input.beauty, roi))
        return false;
    roi.chbegin = 0;
    roi.chend   = c->input.beauty->nchannels();
    ImageBuf result;
    if (ns.empty())
        result = OIIO::ImageBufAlgo::cut(*images[0], roi, nthreads);
    else if (!accumulate_shot(result, *c, ns, offsets, images, roi, nthreads)) {
        dst.errorfmt("{}", result.geterror());
        return false;
    }
    if (!put_result(dst, std::move(result), *images[0], roi, nthreads))
        return false;
    dst.specmod().attribute("mcdenoise:denoise_frames", int(ns.size()) + 1);
    return true;
}

ImageBuf denoise_network(const NetworkFrame& centre, const std::vector<NetworkFrame>& neighbours,
                         const std::vector<int>& offsets, ROI roi, int nthreads)
{
    return value_form([&](ImageBuf& dst) {
        return denoise_network(dst, centre, neighbours, offsets, roi, nthreads);
    });
}

bool denoise_network(ImageBuf& dst, const FrameInput& centre,
                     const std::vector<FrameInput>& neighbours, const std::vector<int>& offsets,
                     const NetworkOptions& options, ROI roi, int nthreads)
{
    if (!centre.beauty) {
        dst.errorfmt("{}: the centre frame has no beauty", temporal_op);
        return false;
    }
    if (!check_neighbours(dst, centre, neighbours, offsets))
        return false;
    if (neighbours.empty())
        return denoise_network(dst, *centre.beauty, network_guides(centre), options, roi, nthreads);
    const NetworkFrame c = prepare_network_frame(centre, options, nthreads);
    std::vector<NetworkFrame> ns;
    for (const FrameInput& n : neighbours)
        ns.push_back(prepare_network_frame(n, options, nthreads));
    return denoise_network(dst, c, ns, offsets, roi, nthreads);
}

ImageBuf denoise_network(const FrameInput& centre, const std::vector<FrameInput>& neighbours,
                         const std::vector<int>& offsets, const NetworkOptions& options, ROI roi,
                         int nthreads)
{
    return value_form([&](ImageBuf& dst) {
        return denoise_network(dst, centre, neighbours, offsets, options, roi, nthreads);
    });
}

}  // namespace mcdenoise
