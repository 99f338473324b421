// temporal_frame.cpp: preparing one frame of a shot for the cross-frame
// denoise, once for every window it is in.
#include "shots/temporal_frame.h"

#include "core/guides.h"
#include "denoise/energy_outliers.h"

#include <algorithm>
#include <memory>

namespace mcdenoise {

using OIIO::ImageBuf;
using OIIO::ROI;

namespace {

// The excess of `f`'s outliers given out over its data window `dw` as its
// own `denoise` does it: spread wide (known fireflies), or each over its
// own window of the frame's planes.
Planes<float> given_excess(const PreparedFrameData& f, const ROI& dw, int nthreads)
{
    ExcessWeights weights = firefly_sources(f.frame, dw, dw);
    if (!weights.wide) {
        const FeatureInputs& p = f.planes;
        fill_outside(weights, ROI(0, 0, 0, 0), own_window(p), p.colour, p.variance, dw,
                     denoise_patch_radius, f.frame.strength, nthreads);
        normalise_weights(weights);
    }
    return spread_excess_planes(weights, f.frame.excess, dw, nthreads);
}

// `denoise`'s steps on `f` over its data window, then its planes, into
// `out`.
bool prepare(ImageBuf& dst, const FrameInput& f, int nthreads, PreparedFrameData& out)
{
    if (!check_frame(dst, f, "frame", f.beauty ? f.beauty->roi() : ROI()))
        return false;
    ROI dw     = f.beauty->roi();
    dw.chbegin = 0;
    dw.chend   = f.beauty->nchannels();
    out.input  = f;
    if (!prepare_denoise_frame(dst, *f.beauty, f.guides, dw, nthreads, out.frame)
        || !load_feature_inputs(temporal_op, dst, out.frame.clamped, out.frame.guides,
                                temporal_feature_sigmas, dw, dw, nthreads, out.planes)
        || (f.guides.motion
            && !load_guide_channels(temporal_op, dst, *f.guides.motion, f.beauty->roi(),
                                    nthreads, out.motion)))
        return false;
    out.given_excess = given_excess(out, f.beauty->roi(), nthreads);
    // Read into the planes and the excess given out: not needed again.
    out.frame.guides = Guides();
    out.frame.variance.reset();
    out.frame.excess = Planes<float>();
    return true;
}

// Which guides a frame has that `denoise` reads, as flags in the order of
// `Guides`.
std::string guide_set(const Guides& g)
{
    std::string s;
    for (const ImageBuf* p : { g.normal, g.depth, g.albedo, g.variance, g.half_a, g.half_b })
        s += p ? '1' : '0';
    return s;
}

bool same_window(const ROI& a, const ROI& b)
{
    return a.xbegin == b.xbegin && a.xend == b.xend && a.ybegin == b.ybegin && a.yend == b.yend
           && a.zbegin == b.zbegin && a.zend == b.zend;
}

// A prepared frame's data, or an error naming it (`what`).
const PreparedFrameData* prepared_frame_data(ImageBuf& dst, const PreparedFrame& f,
                                             const std::string& what)
{
    if (!f.error.empty())
        dst.errorfmt("{}: {}: {}", temporal_op, what, f.error);
    else if (!f.data)
        dst.errorfmt("{}: {}: not prepared", temporal_op, what);
    return f.data.get();
}

}  // namespace

bool check_frame(ImageBuf& dst, const FrameInput& frame, const std::string& what,
                 const ROI& roi)
{
    const std::string op = std::string(temporal_op) + ": " + what;
    if (!frame.beauty) {
        dst.errorfmt("{}: no beauty", op);
        return false;
    }
    return check_denoise_guides(op.c_str(), dst, *frame.beauty, frame.guides, roi)
           && (!frame.guides.motion
               || check_guide(op.c_str(), "motion", dst, *frame.guides.motion, 4, roi));
}

bool check_neighbours(ImageBuf& dst, const FrameInput& centre,
                      const std::vector<FrameInput>& neighbours, const std::vector<int>& offsets)
{
    if (neighbours.size() != offsets.size()) {
        dst.errorfmt("{}: {} neighbour frames but {} offsets", temporal_op, neighbours.size(),
                     offsets.size());
        return false;
    }
    for (size_t i = 0; i < neighbours.size(); ++i) {
        const std::string what = "neighbour frame at offset " + std::to_string(offsets[i]);
        if (offsets[i] == 0 || std::count(offsets.begin(), offsets.end(), offsets[i]) > 1) {
            dst.errorfmt("{}: {}: offsets must be non-zero and distinct", temporal_op, what);
            return false;
        }
        const FrameInput& n = neighbours[i];
        if (!check_frame(dst, n, what, n.beauty ? n.beauty->roi() : ROI()))
            return false;
        if (!same_window(n.beauty->roi(), centre.beauty->roi())
            || n.beauty->nchannels() != centre.beauty->nchannels()) {
            dst.errorfmt("{}: {}: data window or channel count differs from the centre frame's",
                         temporal_op, what);
            return false;
        }
        if (guide_set(n.guides) != guide_set(centre.guides)) {
            dst.errorfmt("{}: {}: has not the centre frame's set of guides", temporal_op, what);
            return false;
        }
    }
    return true;
}

bool shot_data(ImageBuf& dst, const PreparedFrame& centre,
               const std::vector<PreparedFrame>& neighbours, const std::vector<int>& offsets,
               const PreparedFrameData*& c, std::vector<const PreparedFrameData*>& ns)
{
    c = prepared_frame_data(dst, centre, "centre frame");
    std::vector<FrameInput> inputs;
    for (size_t i = 0; c && i < neighbours.size(); ++i) {
        const std::string what = i < offsets.size()
                                     ? "neighbour frame at offset " + std::to_string(offsets[i])
                                     : "neighbour frame " + std::to_string(i);
        ns.push_back(prepared_frame_data(dst, neighbours[i], what));
        if (!ns.back())
            return false;
        inputs.push_back(ns.back()->input);
    }
    return c && check_neighbours(dst, c->input, inputs, offsets);
}

PreparedFrame prepare_frame(const FrameInput& frame, int nthreads)
{
    PreparedFrame out;
    ImageBuf errors;
    auto data = std::make_shared<PreparedFrameData>();
    if (prepare(errors, frame, nthreads, *data))
        out.data = std::move(data);
    else
        out.error = errors.has_error() ? errors.geterror()
                                       : std::string(temporal_op) + ": frame: preparing failed";
    return out;
}

}  // namespace mcdenoise
