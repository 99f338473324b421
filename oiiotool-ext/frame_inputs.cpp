// frame_inputs.cpp: reading one frame's input, beauty and guides.
#include "frame_inputs.h"

#include "frames.h"
#include "guides.h"
#include "memory_limit.h"

namespace mcdtool {

namespace {

/// Float bytes a frame holds at its peak: the input and its output copy,
/// the beauty before, current and being written, and the guides; with
/// --temporal, also its preparation for the cross-frame denoise (the
/// clamped beauty, its excess and its values: 3 planes per beauty
/// channel; colour and variance with their luminance, 8; at most 7
/// feature and 4 motion planes).
uint64_t frame_bytes(const ImageBuf& input, const Discovery& found, const GuideImages& guides, bool temporal)
{
    constexpr uint64_t beauty_buffers = 3, prepared_per_channel = 3, prepared_planes = 8 + 7 + 4;
    uint64_t channels = 2 * uint64_t(input.nchannels()) + beauty_buffers * found.beauty.size();
    for (const auto& [role, guide] : guides.images)
        channels += uint64_t(guide.nchannels());
    if (temporal)
        channels += prepared_per_channel * found.beauty.size() + prepared_planes;
    return float_bytes(input.spec().image_pixels(), channels);
}

}  // namespace

FrameReading frame_reading(const Options& options)
{
    return FrameReading{ options.input, options.beauty_channels, options.aovs,
                         roles_used(options.steps, options.temporal > 0), options.temporal,
                         options.memory_limit_mb };
}

std::string path_for_frame(const std::string& path, std::optional<int> frame)
{
    return frame ? frame_path(path, *frame) : path;
}

std::unique_ptr<FrameInputs> read_frame_inputs(const FrameReading& reading, std::optional<int> frame, RunStats& stats)
{
    PathForFrame path_of = [&](const std::string& path) { return path_for_frame(path, frame); };
    auto inputs = std::make_unique<FrameInputs>();
    inputs->path = path_of(reading.input);
    const uint64_t memory_limit = memory_limit_bytes(reading.memory_limit_mb);
    inputs->files = std::make_unique<ImageFiles>(stats, memory_limit);
    inputs->input = &inputs->files->get(inputs->path, "input");
    const ImageBuf& input = *inputs->input;
    warn_if_display_referred(input, "input");
    inputs->found = discover_channels(input.spec(), reading.beauty_channels, inputs->path);
    inputs->guides =
        load_guides(input, inputs->path, inputs->found, reading.aovs, reading.roles, path_of, *inputs->files);
    require_memory(frame_bytes(input, inputs->found, inputs->guides, reading.temporal > 0 && frame), memory_limit,
                   inputs->path,
                   reading.temporal > 0 && frame
                       ? "this frame (input, output copy, 3 beauty buffers, the guides and the frame prepared for "
                         "--temporal, as float)"
                       : "this frame (input, output copy, 3 beauty buffers and the guides, as float)");
    inputs->beauty = extract_channels(input, inputs->found.beauty);
    return inputs;
}

}  // namespace mcdtool
