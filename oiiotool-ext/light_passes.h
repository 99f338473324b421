// light_passes.h: the light passes `--aovs` denoises with the beauty:
// finding them by name (Cycles, Arnold, RenderMan, testrender) or as
// listed, and rebuilding a Cycles-style beauty from the denoised passes,
// beauty = sum of Col x (Dir + Ind) + the passes added as they are.
#pragma once

#include "channels.h"

#include <OpenImageIO/imagebuf.h>

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace mcdtool {

/// One light pass of the input.
struct LightPass {
    std::string name;           ///< the pass name as in the file ("DiffDir", "RGBA_key")
    std::vector<int> channels;  ///< its channels matching the beauty's colour, in that order
    std::vector<int> colour;    ///< Cycles: the colour pass it is multiplied by; empty: added as is
    /// The rebuild of the beauty it is a term of (`known_rebuilds`' index
    /// of the passes that add up with it), -1 for none.
    int sum = -1;
};

/// The passes `--aovs auto` takes, by renderer: ("Arnold", "direct, ...,
/// RGBA_<group>"), for --help and docs/mcdtool.md.
std::vector<std::pair<std::string, std::string>> known_light_passes();

/// The passes that add up to the beauty together, one list a rebuild, by
/// renderer: (renderer, "DiffDir + ... + Env"), for --help and
/// docs/mcdtool.md. A light-group prefix stands for every group.
std::vector<std::pair<std::string, std::string>> known_rebuilds();

/// The light passes `request` ("auto" or a comma list of pass names) names
/// in the beauty's view layer of `spec`. "auto" takes every known additive
/// light pass present (docs/mcdtool.md, "Light passes"); a list takes the
/// passes named, and throws RunError "--aovs : ..." naming one that is
/// missing, a colour pass, a guide or the beauty.
std::vector<LightPass> find_light_passes(const ImageSpec& spec, std::string_view request,
                                         const Discovery& found, std::string_view file);

/// The light passes and their images for one frame.
struct LightLayers {
    std::vector<LightPass> passes;
    std::vector<ImageBuf> images;   ///< each pass's channels, denoised in place
    std::vector<ImageBuf> colours;  ///< each pass's colour pass (empty image if none)
    bool rebuild = false;           ///< the beauty is rebuilt from the passes after denoising
};

/// Extract `passes` from `input`. `rebuild` is set when some pass has a
/// colour pass and the raw passes rebuild the raw `beauty` (relMSE at most
/// `rebuild_relmse_tolerance`); with a colour pass but no such match, a warning
/// says the beauty is denoised on its own.
LightLayers load_light_layers(const ImageBuf& input, std::vector<LightPass> passes,
                              const ImageBuf& beauty, std::string_view file);

/// The most relMSE between the raw beauty and the raw passes' rebuild for
/// the passes to count as complete.
constexpr double rebuild_relmse_tolerance = 1e-4;

/// `beauty` with its colour channels replaced by the rebuild of `layers`:
/// sum over the passes of the Cycles rebuild (`LightPass::sum`, the one
/// with colour passes) of Col x (Dir + Ind) (passes sharing a colour pass
/// added first, as a compositor does) plus Emit and Env; light groups are
/// a rebuild of their own and not added.
ImageBuf rebuild_beauty(const LightLayers& layers, const ImageBuf& beauty);

/// The input channels written for the beauty and the layers, and their
/// pixels (the beauty's channels, then each layer's), for compose_output.
std::vector<int> written_channels(const std::vector<int>& beauty, const LightLayers& layers);
ImageBuf written_pixels(const ImageBuf& beauty, const LightLayers& layers);

}  // namespace mcdtool
