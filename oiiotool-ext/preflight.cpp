// preflight.cpp: argument checks against the OCIO config, the library's
// own parameter rules and the first frame's headers.
#include "preflight.h"

#include "channels.h"
#include "commands.h"
#include "error.h"
#include "foreign_motion.h"
#include "frame_inputs.h"
#include "frames.h"
#include "light_passes.h"
#include "parts.h"
#include "preview.h"
#include "roles.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <OpenImageIO/strutil.h>

#include <algorithm>
#include <cstdio>

namespace mcdtool {

using OIIO::Strutil::fmt::format;

namespace {

/// The header of `path` (all parts merged), or nullopt if it cannot be read
/// (the frame's run then reports why).
std::optional<ImageSpec> header(const std::string& path)
{
    auto in = OIIO::ImageInput::open(path);
    if (!in) {
        OIIO::geterror();
        return std::nullopt;
    }
    const std::vector<Part> parts = file_parts(path, "input");
    return parts.empty() ? in->spec() : merged_spec(parts);
}

/// The first frame of `frame_list` (--frames) whose `input` exists.
std::optional<std::optional<int>> first_readable_frame(const std::string& frame_list, const std::string& input)
{
    for (const std::optional<int>& frame : frames_to_run(frame_list))
        if (OIIO::Filesystem::exists(path_for_frame(input, frame)))
            return frame;
    return std::nullopt;
}

/// The channel selectors (--beauty, --aov ...:CHANNELS) of `reading` and
/// `light_passes` (--aovs) against the headers of `frame`'s files.
void check_selectors(const FrameReading& reading, const std::string& light_passes, std::optional<int> frame)
{
    auto path_of = [&](const std::string& path) { return path_for_frame(path, frame); };
    if (!reading.beauty_channels.empty() || !light_passes.empty())
        if (auto spec = header(path_of(reading.input))) {
            const Discovery found = discover_channels(*spec, reading.beauty_channels, path_of(reading.input));
            if (!light_passes.empty())
                find_light_passes(*spec, light_passes, found, path_of(reading.input));
        }
    for (const AovRequest& aov : reading.aovs)
        if (!aov.channels.empty())
            if (auto spec = header(path_of(aov.file)))
                select_channels(*spec, aov.channels, path_of(aov.file), "--aov " + aov.typed);
}

/// A 1x1 float image of `nchannels` zeros.
ImageBuf one_pixel(int nchannels)
{
    return ImageBuf(ImageSpec(1, 1, nchannels, OIIO::TypeDesc::FLOAT), OIIO::InitializePixels::Yes);
}

/// Calls every command once on a 1x1 image with a zero guide of each role it
/// needs, so that the parameter rules only the library knows (--dof FOCUS
/// below LEVELS, the widest window it implies) fail before any input is
/// read, with the library's own message. The rules stay in the library.
void check_parameters(const std::vector<Step>& steps)
{
    constexpr int beauty_channels = 3;
    for (const Step& step : steps) {
        if (!step.command)
            continue;
        const Command& command = *step.command;
        GuideImages guides;
        for (Role role : command.roles) {
            const RoleInfo& info = role_info(role);
            guides.images[role] = one_pixel(info.like_beauty ? beauty_channels : info.max_channels);
        }
        ImageBuf beauty = one_pixel(beauty_channels);
        ImageBuf dst;
        Call call{ dst, beauty, guides, step.values, 1, nullptr, nullptr, nullptr, &step.modifiers, 0, false,
                   &command, {} };
        if (!command.call(call) || dst.has_error())
            throw UsageError(format("{} : {}", dashed(command.name), one_line(dst.geterror())));
    }
}

/// `light_passes` (--aovs) needs a command of `steps` that denoises the
/// light passes.
void check_light_passes(const std::string& light_passes, const std::vector<Step>& steps)
{
    if (light_passes.empty()
        || std::any_of(steps.begin(), steps.end(),
                       [](const Step& s) { return s.command && s.command->takes_layers; }))
        return;
    throw UsageError("--aovs : needs --denoise, which denoises the light passes with the beauty");
}

/// Throws unless `temporal` (--temporal N) > 0 comes with what it works on:
/// a sequence (`frame_list`, --frames) and a --denoise first of `steps`, and
/// no `light_passes` (--aovs).
void check_temporal(int temporal, const std::string& frame_list, const std::vector<Step>& steps,
                    const std::string& light_passes)
{
    if (temporal == 0)
        return;
    if (frame_list.empty())
        throw UsageError(format("--temporal {} : needs a frame sequence (a pattern input with --frames)",
                                temporal));
    auto first = std::find_if(steps.begin(), steps.end(), [](const Step& step) { return step.command != nullptr; });
    if (first == steps.end() || std::string(first->command->name) != "denoise")
        throw UsageError(format("--temporal {} : only --denoise works across frames, and it must be the first "
                                "command (the neighbouring frames enter it as read)", temporal));
    if (!light_passes.empty())
        throw UsageError(format("--temporal {} : cannot be combined with --aovs: the light passes are denoised "
                                "one frame at a time (run --aovs without --temporal)", temporal));
}

/// With --temporal, warns once when `frame`'s input (read as `reading`
/// says) has no motion guide but another renderer's motion pass that
/// mcdtool does not convert.
void warn_foreign_motion(const FrameReading& reading, std::optional<int> frame)
{
    const bool given = std::any_of(reading.aovs.begin(), reading.aovs.end(),
                                   [](const AovRequest& aov) { return aov.role == Role::motion; });
    if (reading.temporal == 0 || given)
        return;
    const std::string path = path_for_frame(reading.input, frame);
    auto spec = header(path);
    if (!spec)
        return;
    Discovery found = discover_channels(*spec, reading.beauty_channels, path);
    std::string foreign = found.roles.count(Role::motion) ? "" : foreign_motion_pass(*spec, found.layer);
    if (!foreign.empty())
        std::fprintf(stderr,
                     "mcdtool WARNING: --temporal : %s is not used as the motion guide: %s; the neighbours are "
                     "matched by the patch search alone (give --aov motion=FILE:CHANNELS in Cycles' Vector "
                     "convention, docs/mcdtool.md)\n",
                     path.c_str(), foreign.c_str());
}

}  // namespace

std::vector<std::optional<int>> frames_to_run(const std::string& frame_list)
{
    std::vector<std::optional<int>> frames;
    if (frame_list.empty())
        frames.push_back(std::nullopt);
    else
        for (int frame : parse_frame_list(frame_list))
            frames.push_back(frame);
    return frames;
}

void check_arguments(const Options& options)
{
    check_parameters(options.steps);
    check_light_passes(options.light_passes, options.steps);
    try {
        if (!options.preview.empty() || options.display.given())
            check_display(options.display);
        check_temporal(options.temporal, options.frames, options.steps, options.light_passes);
        if (auto frame = first_readable_frame(options.frames, options.input)) {
            const FrameReading reading = frame_reading(options);
            check_selectors(reading, options.light_passes, *frame);
            warn_foreign_motion(reading, *frame);
        }
    } catch (const RunError& error) {
        throw UsageError(error.what());
    }
}

}  // namespace mcdtool
