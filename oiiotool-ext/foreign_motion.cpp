// foreign_motion.cpp: the table of other renderers' motion passes and their
// lookup.
#include "foreign_motion.h"

#include "channel_names.h"

#include <OpenImageIO/strutil.h>

#include <vector>

namespace mcdtool {

namespace {

/// A motion pass of another renderer, and why it is not a motion guide.
struct ForeignPass {
    const char* pass;
    const char* why;
};

/// Arnold's built-in motionvector AOV is 2D (one direction only) and spans
/// the shutter interval, not a frame, unless written raw with an
/// instantaneous shutter; RenderMan's denoise channels forward (motionFore)
/// and backward (motionBack) are 3-component vectors whose film scale and
/// orientation its documentation does not state.
const std::vector<ForeignPass> foreign_passes = {
    { "motionvector", "Arnold's motionvector AOV: one 2D vector over the shutter interval, not to each "
                      "neighbouring frame" },
    { "forward", "RenderMan's motionFore: film scale and orientation not documented" },
    { "backward", "RenderMan's motionBack: film scale and orientation not documented" },
};

}  // namespace

std::string foreign_motion_pass(const OIIO::ImageSpec& spec, const std::string& layer)
{
    for (const ForeignPass& foreign : foreign_passes)
        for (int c = 0; c < spec.nchannels; ++c) {
            ChannelName name = split_name(spec.channel_name(c));
            if (name.layer == layer && OIIO::Strutil::iequals(name.pass, foreign.pass))
                return OIIO::Strutil::fmt::format("{} ({})", name.layer.empty() ? name.pass
                                                                               : name.layer + "." + name.pass,
                                                  foreign.why);
        }
    return "";
}

}  // namespace mcdtool
