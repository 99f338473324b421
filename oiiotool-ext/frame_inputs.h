// frame_inputs.h: one frame's input as the commands see it: the file read,
// where its beauty and guides are, the guide images and the beauty as
// float. Read once per frame by the runner, or held across frames by the
// --temporal window (frame_window.h).
#pragma once

#include "channels.h"
#include "commands.h"
#include "input.h"
#include "options.h"
#include "runstats.h"

#include <memory>
#include <optional>
#include <string>

namespace mcdtool {

/// One frame's input.
struct FrameInputs {
    std::string path;                    ///< the input file of the frame
    std::unique_ptr<ImageFiles> files;   ///< every file the frame read (input, --aov files)
    const ImageBuf* input = nullptr;     ///< the input file's image, in `files`
    Discovery found;
    Guides guides;
    ImageBuf beauty;                     ///< the beauty channels as float
};

/// Maps `path` (maybe a frame pattern) to frame `frame`'s file.
std::string path_for_frame(const std::string& path, std::optional<int> frame);

/// Reads frame `frame` of `options` (nullopt: the single input image): the
/// input, its beauty and every guide the commands need or use (within the
/// memory limit). Throws RunError naming the file.
std::unique_ptr<FrameInputs> read_frame_inputs(const Options& options, std::optional<int> frame,
                                               RunStats& stats);

}  // namespace mcdtool
