// foreign_motion.h: motion passes other renderers write in conventions the
// motion guide cannot take (Arnold's 2D motionvector AOV, RenderMan's
// denoise forward/backward channels): recognised by name so that a
// cross-frame run says why it goes without motion instead of silently
// ignoring them.
#pragma once

#include <OpenImageIO/imagebuf.h>

#include <string>

namespace mcdtool {

/// "ViewLayer.motionvector (Arnold: ...)": the first pass of view layer
/// `layer` of `spec` that another renderer writes as screen-space motion
/// in a convention mcdtool does not convert, with the reason; "" if none.
std::string foreign_motion_pass(const OIIO::ImageSpec& spec, const std::string& layer);

}  // namespace mcdtool
