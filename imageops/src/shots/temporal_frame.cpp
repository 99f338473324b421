// temporal_frame.cpp: preparing one frame of a shot for the cross-frame
// denoise, once for every window it is in.
#include "shots/temporal_frame.h"

#include "core/guides.h"
#include "denoise/energy_outliers.h"

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
