// frame.h: running the whole command line on one image (or one frame of a
// sequence): read, find beauty and guides, run the commands left to right,
// write every -o and --preview, then rename them all into place.
#pragma once

#include "options.h"
#include "runstats.h"

#include <optional>

namespace mcdtool {

/// Runs `options` on `frame` (nullopt: the single input image). Throws
/// RunError naming the culprit; then nothing of this frame is written.
FrameOutcome run_frame(const Options& options, std::optional<int> frame, RunStats& stats);

}  // namespace mcdtool
