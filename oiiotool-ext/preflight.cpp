// preflight.cpp: argument checks against the OCIO config and the first
// frame's headers.
#include "preflight.h"

#include "channels.h"
#include "error.h"
#include "frames.h"
#include "preview.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

namespace mcdtool {

namespace {

/// The header of `path` (subimage 0), or nullopt if it cannot be read
/// (the frame's run then reports why).
std::optional<ImageSpec> header(const std::string& path)
{
    auto in = OIIO::ImageInput::open(path);
    if (!in) {
        OIIO::geterror();
        return std::nullopt;
    }
    return in->spec();
}

/// The first frame whose input exists.
std::optional<std::optional<int>> first_readable_frame(const Options& options)
{
    for (const std::optional<int>& frame : frames_to_run(options))
        if (OIIO::Filesystem::exists(frame ? frame_path(options.input, *frame) : options.input))
            return frame;
    return std::nullopt;
}

/// The channel selectors (--beauty, --aov ...:CHANNELS) against the
/// headers of `frame`'s files.
void check_selectors(const Options& options, std::optional<int> frame)
{
    auto path_of = [&](const std::string& path) { return frame ? frame_path(path, *frame) : path; };
    if (!options.beauty_channels.empty())
        if (auto spec = header(path_of(options.input)))
            discover_channels(*spec, options.beauty_channels, path_of(options.input));
    for (const AovRequest& aov : options.aovs)
        if (!aov.channels.empty())
            if (auto spec = header(path_of(aov.file)))
                select_channels(*spec, aov.channels, path_of(aov.file), "--aov " + aov.typed);
}

}  // namespace

std::vector<std::optional<int>> frames_to_run(const Options& options)
{
    std::vector<std::optional<int>> frames;
    if (options.frames.empty())
        frames.push_back(std::nullopt);
    else
        for (int frame : parse_frame_list(options.frames))
            frames.push_back(frame);
    return frames;
}

void check_arguments(const Options& options)
{
    try {
        if (!options.preview.empty() || !options.display.empty() || !options.view.empty()
            || !options.ocio_config.empty())
            check_display(options);
        if (auto frame = first_readable_frame(options))
            check_selectors(options, *frame);
    } catch (const RunError& error) {
        throw UsageError(error.what());
    }
}

}  // namespace mcdtool
