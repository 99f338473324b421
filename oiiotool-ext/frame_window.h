// frame_window.h: the frames a --temporal N run holds in memory: each
// frame's inputs read once, and prepared for the cross-frame denoise once,
// and kept while within N frames of the frame being run (a sliding window
// of 2N+1 frames when the frames run in order), and the neighbours of a
// frame as --denoise takes them.
#pragma once

#include "commands.h"
#include "frame_inputs.h"
#include "runstats.h"

#include <mcdenoise/denoise_network.h>
#include <mcdenoise/temporal.h>

#include <map>
#include <memory>
#include <utility>
#include <vector>

namespace mcdtool {

/// The frames held by a --temporal run.
class FrameWindow {
public:
    /// A window of the frames read as `reading` says, N = `reading.temporal`.
    FrameWindow(FrameReading reading, RunStats& stats) : reading_(std::move(reading)), stats_(stats) {}

    /// The inputs of `frame`, read now unless held; drops the held frames
    /// farther than N from it. Throws RunError naming the file.
    const FrameInputs& centre(int frame);

    /// `frame` as --denoise takes it (offset 0), read unless held.
    WindowFrame centre_frame(int frame);

    /// The frames `frame` +- 1..N whose input file exists, read unless held
    /// (`centre(frame)` first), each checked against the centre: the same
    /// display and data window, beauty channel count and guides (a
    /// neighbour may lack the motion guide), else
    /// RunError naming both frames. A neighbour missing on disk is warned
    /// about on stderr and left out.
    std::vector<WindowFrame> neighbours(int frame);

private:
    /// A frame held: its inputs and, once --denoise has made them, its
    /// preparation for the cross-frame denoise and its network result.
    struct Held {
        std::unique_ptr<FrameInputs> inputs;
        std::unique_ptr<mcdenoise::PreparedFrame> prepared;
        std::unique_ptr<mcdenoise::NetworkFrame> network;
    };

    /// `frame`, read now unless held.
    Held& get(int frame);

    const FrameReading reading_;
    RunStats& stats_;
    std::map<int, Held> held_;
};

}  // namespace mcdtool
