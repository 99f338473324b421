// driver.cpp: mcdtool's program logic: parse and check the arguments, then
// run every frame, report errors with the frame number, print --runstats
// and a sequence's summary, choose the exit status.
#include "driver.h"

#include "error.h"
#include "frame.h"
#include "frame_inputs.h"
#include "frame_window.h"
#include "help.h"
#include "options.h"
#include "preflight.h"
#include "runstats.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cstdio>
#include <optional>

namespace mcdtool {

namespace {

/// Prints a one-line error on stderr.
void print_error(const std::string& message)
{
    std::fprintf(stderr, "mcdtool ERROR: %s\n", message.c_str());
}

/// Runs every frame (or the single image); returns the exit status.
int run(const Options& options)
{
    const std::vector<std::optional<int>> frames = frames_to_run(options.frames);
    RunStats stats;
    Progress progress(frames.size());
    stats.show_progress_in(&progress);
    FrameWindow window(frame_reading(options), stats);
    const bool sequence = !options.frames.empty();
    std::optional<SequenceCompare> compare;
    if (sequence && !options.compare.empty())
        compare.emplace(options.threads);
    const SequenceRun shared{ &window, compare ? &*compare : nullptr };
    size_t done = 0;
    for (const std::optional<int>& frame : frames) {
        std::string where = frame ? "frame " + std::to_string(*frame) + ": " : "";
        FrameOutcome outcome = FrameOutcome::failed;
        progress.begin_frame(done + 1, frame.value_or(0));
        try {
            outcome = run_frame(options, frame, stats, shared);
            if (outcome == FrameOutcome::skipped && options.verbose) {
                progress.clear();
                std::printf("mcdtool: %sskipped, outputs exist\n", where.c_str());
            }
        } catch (const RunError& error) {
            progress.clear();
            print_error(where + error.what());
        } catch (const std::exception& error) {
            progress.clear();
            print_error(where + "internal error: " + error.what());
        }
        stats.add_frame(outcome);
        progress.update(++done, frame.value_or(0));
    }
    progress.finish();
    stats.show_progress_in(nullptr);
    if (compare)
        compare->print();
    if (options.runstats)
        std::printf("%s", stats.report().c_str());
    if (sequence)  // on and off a terminal: farm logs are files
        std::fprintf(stderr, "mcdtool: %s\n", stats.frame_summary().c_str());
    return stats.frames(FrameOutcome::failed) ? exit_run_error : exit_ok;
}

}  // namespace

int run_mcdtool(const std::vector<std::string>& args)
{
    if (args.empty()) {
        std::fprintf(stderr, "%s", help_text().c_str());
        return exit_usage_error;
    }
    Options options;
    try {
        options = parse_command_line(args);
    } catch (const UsageError& error) {
        print_error(error.what());
        return exit_usage_error;
    }
    switch (options.mode) {
    case Mode::help: std::printf("%s", help_text().c_str()); return exit_ok;
    case Mode::help_markdown: std::printf("%s", help_markdown().c_str()); return exit_ok;
    case Mode::version: std::printf("%s\n", version_text().c_str()); return exit_ok;
    case Mode::run: break;
    }
    bool writes = options.preview.size() || options.compare.size()
                  || std::any_of(options.steps.begin(), options.steps.end(), [](const Step& s) { return !s.command; });
    if (!writes && !options.verbose)
        std::fprintf(stderr, "mcdtool WARNING: no -o, --compare or --preview: the result goes nowhere\n");
    try {
        check_arguments(options);
    } catch (const UsageError& error) {
        print_error(error.what());
        return exit_usage_error;
    }
    OIIO::attribute("threads", options.threads);
    return run(options);
}

}  // namespace mcdtool
