// output.h: the render as one float OpenEXR image: beauty, AOV channels and
// metadata, with testrender's channel names.
#pragma once

#include "render.h"

#include <OpenImageIO/imagebuf.h>

#include <string>

namespace testrender {

/// Channel names in file order: R,G,B, albedo.{R,G,B}, N.{X,Y,Z}, Z, id,
/// reflid, var.{R,G,B}, A.{R,G,B}, B.{R,G,B}, motion.{X,Y,Z,W}; then A (the
/// alpha) if the buffers have one, then the light passes if they have them.
std::vector<std::string> channel_names(const RenderBuffers& buffers);

/// The buffers as a float ImageBuf with the channels above and the metadata
/// testrender:scene, testrender:spp, testrender:seed, testrender:frame,
/// testrender:render_seconds and testrender:samples_per_second.
OIIO::ImageBuf to_image(const RenderBuffers& buffers, const std::string& scene_name,
                        const RenderSettings& settings);

/// Write `image` to `path` (ZIP-compressed float EXR) through a temporary
/// file renamed into place, so a reader never sees a partial file. On
/// failure returns false and sets `error`.
bool write_image(const OIIO::ImageBuf& image, const std::string& path, std::string& error);

}  // namespace testrender
