// channels.h: finding the beauty and the guides among an image's channels:
// testrender's names (R,G,B, albedo.R, N.X, Z, id, reflid, var.R, A.R, B.R),
// Blender Cycles multilayer EXR (<ViewLayer>.Combined.R, .IndexOB.X,
// .Normal.X, .Depth.Z, .Denoising Albedo.R, ...), RenderMan's and Arnold's
// denoise AOVs (Ci, mse, zfiltered; RGBA, variance, denoise_albedo, N, Z)
// and explicit selectors (a comma list of channel names or a layer prefix).
#pragma once

#include "channel_names.h"
#include "roles.h"

#include <OpenImageIO/imagebuf.h>

#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace mcdtool {

using OIIO::ImageBuf;

/// What discovery found in one image's channel list.
struct Discovery {
    std::vector<int> beauty;                 ///< channel indices to filter
    std::string layer;                       ///< the beauty's view layer ("" if none)
    std::map<Role, std::vector<int>> roles;  ///< guides found beside it
};

/// Channel indices chosen by `selector` in `spec`: a comma list of channel
/// names, each one exact or a layer prefix ("N" selects N.X,N.Y,N.Z), in the
/// order given. Throws RunError naming `file` and listing its channels.
std::vector<int> select_channels(const ImageSpec& spec, std::string_view selector,
                                 std::string_view file, std::string_view context);

/// Indices of the channels of pass `pass` in view layer `layer` (pass name
/// compared without case), in file order.
std::vector<int> pass_channels(const ImageSpec& spec, const std::string& layer, const std::string& pass);

/// The channels of `candidate` whose components match those of `beauty`,
/// in the beauty's order (for half_a / half_b and light passes); empty if
/// any is missing.
std::vector<int> matching_components(const ImageSpec& spec, const std::vector<int>& candidate,
                                     const std::vector<int>& beauty);

/// Finds the beauty (or takes `beauty_selector` if not empty) and every
/// guide role in the beauty's view layer; with no id pass, a Cryptomatte
/// object layer's rank-0 ids stand in for it. Throws RunError if there is
/// no beauty.
Discovery discover_channels(const ImageSpec& spec, std::string_view beauty_selector,
                            std::string_view file);

/// A float image holding channels `indices` of `src`, in that order.
ImageBuf extract_channels(const ImageBuf& src, const std::vector<int>& indices);

}  // namespace mcdtool
