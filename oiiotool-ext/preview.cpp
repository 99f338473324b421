// preview.cpp: side-by-side panels and the display transform.
#include "preview.h"

#include "error.h"

#include <OpenImageIO/color.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/strutil.h>

#include <algorithm>
#include <cstdlib>
#include <optional>
#include <utility>
#include <vector>

namespace mcdtool {

using OIIO::Strutil::fmt::format;
namespace IBA = OIIO::ImageBufAlgo;

namespace {

/// Channels of a preview panel (RGB).
constexpr int panel_channels = 3;

/// `image` as a 3-channel float panel with its origin at (0, 0): its
/// first three channels, or its first channel repeated.
ImageBuf panel(const ImageBuf& image)
{
    std::vector<int> order(panel_channels, 0);
    if (image.nchannels() >= panel_channels)
        order = { 0, 1, 2 };
    ImageBuf rgb;
    if (!IBA::channels(rgb, image, panel_channels, order))
        throw RunError(format("--preview : {}", one_line(rgb.geterror())));
    rgb.set_origin(0, 0);
    return rgb;
}

/// The panels side by side on a black canvas.
ImageBuf side_by_side(const std::vector<const ImageBuf*>& images)
{
    std::vector<ImageBuf> panels;
    int width = 0;
    int height = 0;
    for (const ImageBuf* image : images) {
        panels.push_back(panel(*image));
        width += panels.back().spec().width;
        height = std::max(height, panels.back().spec().height);
    }
    ImageBuf canvas(OIIO::ImageSpec(width, height, panel_channels, OIIO::TypeDesc::FLOAT));
    IBA::zero(canvas);
    int x = 0;
    for (const ImageBuf& p : panels) {
        if (!IBA::paste(canvas, x, 0, 0, 0, p))
            throw RunError(format("--preview : {}", one_line(canvas.geterror())));
        x += p.spec().width;
    }
    return canvas;
}

/// Throws unless `name` is one of `known` (the config's displays or views).
void require_known(const char* option, const std::string& name, const std::vector<std::string>& known)
{
    if (std::find(known.begin(), known.end(), name) != known.end())
        return;
    throw RunError(format("{} : '{}' is not in the OCIO config (known: {})", option, name,
                          known.empty() ? "none" : OIIO::Strutil::join(known, ", ")));
}

/// The display and view of `config` that --display / --view choose (the
/// config's defaults if not given), checked against the config; nullopt
/// when no config is asked for and the built-in sRGB transform serves.
/// Throws RunError for an unloadable config or an unknown name.
std::optional<std::pair<std::string, std::string>> display_view(OIIO::ColorConfig& config, const DisplayChoice& choice)
{
    bool have_config = !choice.ocio_config.empty() || std::getenv("OCIO");
    if (!have_config) {
        config.geterror();  // no config asked for: the built-in transforms serve
        if (!choice.display.empty() || !choice.view.empty())
            throw RunError("--display / --view : need an OCIO config (--ocio-config FILE or $OCIO)");
        return std::nullopt;
    }
    if (config.has_error())
        throw RunError(format("--ocio-config : cannot load '{}': {}",
                              choice.ocio_config.empty() ? "$OCIO" : choice.ocio_config,
                              one_line(config.geterror())));
    std::string name = choice.display.empty() ? config.getDefaultDisplayName() : choice.display;
    require_known("--display", name, config.getDisplayNames());
    std::string view = choice.view.empty() ? config.getDefaultViewName(name) : choice.view;
    require_known("--view", view, config.getViewNames(name));
    return std::make_pair(name, view);
}

/// `canvas` converted from scene-linear to display values.
ImageBuf to_display(const ImageBuf& canvas, const DisplayChoice& choice)
{
    OIIO::ColorConfig config(choice.ocio_config);
    auto chosen = display_view(config, choice);
    ImageBuf display;
    bool ok = false;
    if (chosen) {
        const char* linear = config.getColorSpaceNameByRole("scene_linear");
        ok = IBA::ociodisplay(display, canvas, chosen->first, chosen->second, linear ? linear : "linear", "", false,
                              "", "", &config);
    } else {
        ok = IBA::colorconvert(display, canvas, "linear", "sRGB", false, "", "", &config);
    }
    if (!ok)
        throw RunError(format("--preview : display transform failed: {}", one_line(display.geterror())));
    return display;
}

}  // namespace

void check_display(const DisplayChoice& choice)
{
    OIIO::ColorConfig config(choice.ocio_config);
    display_view(config, choice);
}

void write_preview(const std::string& path, const ImageBuf& before, const ImageBuf& after,
                   const ImageBuf* reference, const DisplayChoice& choice, OutputBatch& batch)
{
    std::vector<const ImageBuf*> images = { &before, &after };
    if (reference)
        images.push_back(reference);
    ImageBuf display = to_display(side_by_side(images), choice);
    OIIO::ImageSpec spec = display.spec();
    spec.set_format(OIIO::TypeDesc::UINT8);
    batch.write(path, spec, display, "--preview");
}

}  // namespace mcdtool
