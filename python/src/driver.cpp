// driver.cpp: mcdtool's per-frame runner, exposed for the batch module, so a
// frame run from Python reads, finds guides, filters and writes exactly as
// `mcdtool ... --frames` does (one piece of code for both).
#include "driver.h"

#include "oiiotool-ext/error.h"
#include "oiiotool-ext/frame.h"
#include "oiiotool-ext/frame_inputs.h"
#include "oiiotool-ext/frame_window.h"
#include "oiiotool-ext/frames.h"
#include "oiiotool-ext/options.h"
#include "oiiotool-ext/preflight.h"
#include "oiiotool-ext/runstats.h"

#include <pybind11/stl.h>

#include <optional>

namespace mcdpy {

namespace {

/// Parses an mcdtool command line for running (not --help or --version).
mcdtool::Options parse_for_run(const std::vector<std::string>& args)
{
    mcdtool::Options options = mcdtool::parse_command_line(args);
    if (options.mode != mcdtool::Mode::run)
        throw mcdtool::UsageError("--help, --help-markdown and --version do not run frames");
    return options;
}

/// Runs one frame of `args` (nullopt: the single input image).
std::string run_frame(const std::vector<std::string>& args, std::optional<int> frame)
{
    mcdtool::Options options = parse_for_run(args);
    py::gil_scoped_release release;
    mcdtool::RunStats stats;
    return mcdtool::run_frame(options, frame, stats) == mcdtool::FrameOutcome::written ? "written" : "skipped";
}

/// Runs the frames of one batch task in order, sharing what mcdtool's own
/// run shares between frames: with --temporal, the window of frames read
/// (each file of the task's frames and their neighbours read once).
class FrameRunner {
public:
    explicit FrameRunner(const std::vector<std::string>& args)
        : options_(parse_for_run(args)), window_(mcdtool::frame_reading(options_), stats_)
    {
    }
    /// Runs one frame as `_run_frame` does.
    std::string run(std::optional<int> frame)
    {
        py::gil_scoped_release release;
        const mcdtool::SequenceRun shared{ &window_, nullptr };
        return mcdtool::run_frame(options_, frame, stats_, shared) == mcdtool::FrameOutcome::written ? "written"
                                                                                                     : "skipped";
    }

private:
    mcdtool::Options options_;
    mcdtool::RunStats stats_;
    mcdtool::FrameWindow window_;
};

/// The input, --frames and every output pattern of a command line, after
/// mcdtool's checks of every argument value (preflight.h).
py::dict describe_command_line(const std::vector<std::string>& args)
{
    mcdtool::Options options = parse_for_run(args);
    mcdtool::check_arguments(options);
    std::vector<std::string> outputs;
    for (const mcdtool::Step& step : options.steps)
        if (!step.command)
            outputs.push_back(step.output);
    py::dict description;
    description["input"] = options.input;
    description["frames"] = options.frames;
    description["outputs"] = outputs;
    return description;
}

}  // namespace

void bind_driver(py::module_& m)
{
    m.def("_run_frame", &run_frame, py::arg("args"), py::arg("frame") = std::nullopt,
          "Runs mcdtool's command line `args` (without the program name) on one\n"
          "frame, as `mcdtool ARGS` does for that frame: returns 'written' or\n"
          "'skipped' (--skip-existing); raises UsageError or Error with mcdtool's\n"
          "message, in which case nothing of the frame was written.");
    py::class_<FrameRunner>(m, "_FrameRunner",
                            "mcdtool's command line `args` (without the program name), run frame by\n"
                            "frame in order: run(frame) does what _run_frame does, and with --temporal\n"
                            "keeps the frames read for the next frames (each file read once).")
        .def(py::init<const std::vector<std::string>&>(), py::arg("args"))
        .def("run", &FrameRunner::run, py::arg("frame") = std::nullopt);
    m.def("_describe_command_line", &describe_command_line, py::arg("args"),
          "Parses and checks mcdtool's command line `args` as mcdtool does before\n"
          "reading any frame: a dict with its 'input', 'frames' (as typed) and\n"
          "'outputs' (the -o patterns); raises UsageError.");
    m.def("frame_list", &mcdtool::parse_frame_list, py::arg("frames"),
          "The frames of an mcdtool frame list: '1-48', '1-10x2', '10-1', '1,3,5'\n"
          "or mixtures; raises UsageError naming the bad part.");
    m.def("frame_path", &mcdtool::frame_path, py::arg("pattern"), py::arg("frame"),
          "`pattern` with its frame pattern ('#' = 4 digits, '####' or '@@@@' =\n"
          "one digit each, '%04d') replaced by `frame`, as mcdtool does.");
}

}  // namespace mcdpy
