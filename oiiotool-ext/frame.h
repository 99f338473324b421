// frame.h: running the whole command line on one image (or one frame of a
// sequence): read, find beauty and guides, run the commands left to right,
// write every -o and --preview, then rename them all into place.
#pragma once

#include "compare.h"
#include "frame_window.h"
#include "options.h"
#include "runstats.h"

#include <optional>

namespace mcdtool {

/// What the frames of one run share.
struct SequenceRun {
    /// With --temporal: the frames held across the run (nullptr: run_frame
    /// reads the frame's neighbours for this frame alone).
    FrameWindow* window = nullptr;
    /// With --compare over a sequence: the sequence figures (nullptr: none).
    SequenceCompare* compare = nullptr;
};

/// Runs `options` on `frame` (nullopt: the single input image). Throws
/// RunError naming the culprit; then nothing of this frame is written.
FrameOutcome run_frame(const Options& options, std::optional<int> frame, RunStats& stats,
                       const SequenceRun& run = {});

}  // namespace mcdtool
