// frame.cpp: the per-frame runner shared by every command: reading,
// timing, error forwarding ("--median : <library message>") and writing.
#include "frame.h"

#include "channels.h"
#include "compare.h"
#include "error.h"
#include "frame_inputs.h"
#include "memory_limit.h"
#include "frames.h"
#include "guides.h"
#include "input.h"
#include "light_passes.h"
#include "output.h"
#include "parts.h"
#include "preview.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/strutil.h>

#include <cstdio>

namespace mcdtool {

using OIIO::Strutil::fmt::format;

namespace {

/// The dst attribute in which the library counts windows with no finite value.
const char* const empty_windows_attribute = "mcdenoise:empty_windows";

/// A file a frame writes, with the option that names it ("-o", "--preview").
using OutputPath = std::pair<std::string, std::string>;

/// Every file this frame reads as `reading` says, and the --compare
/// reference `compare` (empty: none), for the overwrite check.
std::vector<std::string> input_paths(const FrameReading& reading, const std::string& compare,
                                     const PathForFrame& path_of)
{
    std::vector<std::string> paths = { path_of(reading.input) };
    for (const AovRequest& aov : reading.aovs)
        paths.push_back(path_of(aov.file));
    if (!compare.empty())
        paths.push_back(path_of(compare));
    return paths;
}

/// Every file this frame writes: the -o of `steps`, and `preview` (empty:
/// none).
std::vector<OutputPath> output_paths(const std::vector<Step>& steps, const std::string& preview,
                                     const PathForFrame& path_of)
{
    std::vector<OutputPath> paths;
    for (const Step& step : steps)
        if (!step.command)
            paths.emplace_back("-o", path_of(step.output));
    if (!preview.empty())
        paths.emplace_back("--preview", path_of(preview));
    return paths;
}

/// Throws unless every one of `outputs` can be written: none would replace
/// one of `inputs` or a write-protected file (unless `force`, --force), and
/// the folders exist (made if missing). Runs before any input is read.
void prepare_outputs(const std::vector<OutputPath>& outputs, const std::vector<std::string>& inputs, bool force)
{
    for (const auto& [option, output] : outputs) {
        if (!force)
            for (const std::string& input : inputs)
                if (same_file(output, input))
                    throw RunError(format("{} : '{}' is an input of this run; add --force to replace it", option,
                                          output));
        prepare_output_path(option, output, force);
    }
}

/// True if --skip-existing applies: every one of `outputs` exists.
bool all_outputs_exist(const std::vector<OutputPath>& outputs)
{
    if (outputs.empty())
        return false;
    for (const auto& output : outputs)
        if (!OIIO::Filesystem::exists(output.second))
            return false;
    return true;
}

/// With -v: which channels went to the beauty and to each guide role.
void report_channels(const std::string& input_path, const ImageBuf& input, const Discovery& found,
                     const GuideImages& guides)
{
    std::printf("mcdtool: %-8s <- %s: %s\n", "beauty", input_path.c_str(),
                channel_names(input.spec(), found.beauty).c_str());
    for (const RoleInfo& info : role_table()) {
        auto source = guides.sources.find(info.role);
        if (source != guides.sources.end())
            std::printf("mcdtool: %-8s <- %s\n", info.name, source->second.c_str());
    }
}

/// With -v: the light passes --aovs denoises, and whether the beauty is rebuilt from them.
void report_light_passes(const std::string& input_path, const LightLayers& layers)
{
    std::vector<std::string> names;
    for (const LightPass& pass : layers.passes)
        names.push_back(pass.name);
    std::printf("mcdtool: %-8s <- %s: %s%s\n", "aovs", input_path.c_str(),
                names.empty() ? "(none found)" : OIIO::Strutil::join(names, ",").c_str(),
                layers.rebuild ? " (the beauty is rebuilt from them)" : "");
}

/// With -v and --temporal: the neighbouring frames --denoise takes.
void report_neighbours(int frame, const std::vector<WindowFrame>& neighbours)
{
    std::vector<std::string> frames;
    for (const WindowFrame& n : neighbours)
        frames.push_back(std::to_string(frame + n.offset));
    std::printf("mcdtool: --temporal : frame %d with frames %s\n", frame,
                frames.empty() ? "(none on disk)" : OIIO::Strutil::join(frames, ", ").c_str());
}

/// The frames of a --temporal window a command takes: the frame itself and
/// its neighbours on disk.
struct WindowFrames {
    WindowFrame centre{};
    std::vector<WindowFrame> neighbours;
};

/// What --memory-limit leaves for a command's working memory (the
/// network's tiles) beyond what the process already holds (the frame's
/// images, read and extracted): 0 (no bound) without a limit, at least 1
/// byte with one.
uint64_t network_budget(uint64_t memory_limit_mb)
{
    if (memory_limit_mb == 0)
        return 0;
    const uint64_t limit = memory_limit_mb << 20, held = resident_bytes();
    return limit > held ? limit - held : 1;
}

/// Runs one command on `nthreads` threads: exactly one library call, timed,
/// errors forwarded; with `verbose`, its time is printed. `memory_limit`
/// (bytes, 0 for none) bounds the network's working memory. With `window`,
/// the command takes its frames (--denoise across frames).
ImageBuf run_command(const Step& step, const ImageBuf& current, const GuideImages& guides, LightLayers& layers,
                     int nthreads, bool verbose, uint64_t memory_limit, RunStats& stats,
                     const WindowFrames* window)
{
    const Command& command = *step.command;
    std::string name = dashed(command.name);
    ImageBuf dst;
    Call call{ dst,
               current,
               guides,
               step.values,
               nthreads,
               window ? &window->neighbours : nullptr,
               window ? &window->centre : nullptr,
               command.takes_layers ? &layers : nullptr,
               &step.modifiers,
               memory_limit,
               verbose,
               &command,
               [&stats](double fraction) { stats.command_progress(fraction); } };
    stats.begin_command(step.values.empty() ? name : name + " " + OIIO::Strutil::join(step.values, " "));
    Timer timer;
    bool ok = command.call(call);
    double seconds = timer.seconds();
    stats.add_command(name, seconds);
    if (!ok || dst.has_error())
        throw RunError(format("{} : {}", name, one_line(dst.geterror())));
    int empty = dst.spec().get_int_attribute(empty_windows_attribute, 0);
    if (empty > 0)
        std::fprintf(stderr, "mcdtool WARNING: %s : %d window(s) held no finite value and were set to 0\n",
                     name.c_str(), empty);
    if (verbose)
        std::printf("mcdtool: %s %s  %.3f s\n", name.c_str(), OIIO::Strutil::join(step.values, " ").c_str(),
                    seconds);
    return command.takes_layers && layers.rebuild ? rebuild_beauty(layers, dst) : dst;
}

/// The inputs of one frame, and with --temporal its neighbours on disk.
struct LoadedFrame {
    std::unique_ptr<FrameWindow> own_window;  ///< a window for this frame alone (no shared one)
    std::unique_ptr<FrameInputs> own_inputs;  ///< the inputs, when not held by a window
    const FrameInputs* inputs = nullptr;
    WindowFrames window;  ///< with --temporal
};

/// Reads `frame` as `reading` says, from `window` with --temporal (a window
/// of its own if `window` is nullptr).
LoadedFrame load_frame(const FrameReading& reading, std::optional<int> frame, RunStats& stats,
                       FrameWindow* window)
{
    LoadedFrame loaded;
    if (reading.temporal == 0 || !frame) {
        loaded.own_inputs = read_frame_inputs(reading, frame, stats);
        loaded.inputs = loaded.own_inputs.get();
        return loaded;
    }
    if (!window) {
        loaded.own_window = std::make_unique<FrameWindow>(reading, stats);
        window = loaded.own_window.get();
    }
    loaded.inputs = &window->centre(*frame);
    loaded.window.centre = window->centre_frame(*frame);
    loaded.window.neighbours = window->neighbours(*frame);
    return loaded;
}

}  // namespace

FrameOutcome run_frame(const Options& options, std::optional<int> frame, RunStats& stats, const SequenceRun& run)
{
    PathForFrame path_of = [&](const std::string& path) { return path_for_frame(path, frame); };
    const std::vector<OutputPath> outputs = output_paths(options.steps, options.preview, path_of);
    if (options.skip_existing && all_outputs_exist(outputs))
        return FrameOutcome::skipped;
    const FrameReading reading = frame_reading(options);
    prepare_outputs(outputs, input_paths(reading, options.compare, path_of), options.force);

    const LoadedFrame loaded = load_frame(reading, frame, stats, run.window);
    const FrameInputs& inputs = *loaded.inputs;
    const ImageBuf& input = *inputs.input;
    const std::string& input_path = inputs.path;
    const Discovery& found = inputs.found;
    const GuideImages& guides = inputs.guides;
    const std::vector<Part> parts = file_parts(input_path, "input");
    if (options.verbose)
        report_channels(input_path, input, found, guides);
    if (options.verbose && options.temporal > 0 && frame)
        report_neighbours(*frame, loaded.window.neighbours);
    for (const Step& step : options.steps)  // before any work: fail fast on a missing guide
        if (step.command)
            require_guides(*step.command, guides, input_path, input.spec(), found);
    ImageBuf reference;  // before any work: a missing reference must not cost the result
    if (!options.compare.empty())
        reference = reference_beauty(path_of(options.compare), options.beauty_channels, *inputs.files,
                                     found.beauty.size());

    const ImageBuf& before = inputs.beauty;
    ImageBuf current = before;
    LightLayers layers;
    if (!options.light_passes.empty())
        layers = load_light_layers(input, find_light_passes(input.spec(), options.light_passes, found, input_path),
                                   before, input_path);
    if (options.verbose && !options.light_passes.empty())
        report_light_passes(input_path, layers);
    OutputBatch batch(stats);
    bool first_command = true;  // with --temporal, the --denoise that takes the neighbours (preflight.cpp)
    for (const Step& step : options.steps) {
        if (step.command) {
            const bool across_frames = options.temporal > 0 && frame && first_command;
            current = run_command(step, current, guides, layers, options.threads, options.verbose,
                                  network_budget(options.memory_limit_mb), stats,
                                  across_frames ? &loaded.window : nullptr);
            first_command = false;
            continue;
        }
        std::string path = path_of(step.output);
        OutputImage output = compose_output(input, inputs.files->integer_channels(input),
                                            written_channels(found.beauty, layers), written_pixels(current, layers),
                                            options.format, path);
        if (!parts.empty() && writes_parts(path))
            write_parts(batch, path, parts, output.pixels, options.format, "-o");
        else
            batch.write(path, output.spec, output.pixels, "-o", output.stored);
        if (output.beauty_only && input.nchannels() > int(found.beauty.size()))
            std::fprintf(stderr,
                         "mcdtool WARNING: -o %s : the format cannot keep %d channels by name: the beauty only "
                         "(write EXR to keep every channel)\n",
                         path.c_str(), input.nchannels());
        if (options.verbose)
            std::printf("mcdtool: -o %s\n", path.c_str());
    }
    if (!options.compare.empty())
        print_comparison(path_of(options.compare), before, current, reference, options.threads);
    if (!options.preview.empty()) {
        write_preview(path_of(options.preview), before, current,
                      options.compare.empty() ? nullptr : &reference, options.display, batch);
        if (options.verbose)
            std::printf("mcdtool: --preview %s\n", path_of(options.preview).c_str());
    }
    batch.commit();
    if (run.compare)
        run.compare->add(before, current, reference);
    return FrameOutcome::written;
}

}  // namespace mcdtool
