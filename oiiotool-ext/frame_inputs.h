// frame_inputs.h: one frame's input as the commands see it: the file read,
// where its beauty and guides are, the guide images and the beauty as
// float; and what reading it takes of the command line (FrameReading).
// Read once per frame by the runner, or held across frames by the
// --temporal window (frame_window.h).
#pragma once

#include "channels.h"
#include "commands.h"
#include "input.h"
#include "options.h"
#include "roles.h"
#include "runstats.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace mcdtool {

/// One frame's input.
struct FrameInputs {
    std::string path;                    ///< the input file of the frame
    std::unique_ptr<ImageFiles> files;   ///< every file the frame read (input, --aov files)
    const ImageBuf* input = nullptr;     ///< the input file's image, in `files`
    Discovery found;
    GuideImages guides;
    ImageBuf beauty;                     ///< the beauty channels as float
};

/// What reading a frame's inputs takes of the command line.
struct FrameReading {
    std::string input;               ///< may hold a frame pattern
    std::string beauty_channels;     ///< --beauty (empty: discover)
    std::vector<AovRequest> aovs;    ///< --aov
    std::set<Role> roles;            ///< the guide roles the commands need or use
    int temporal = 0;                ///< --temporal: frames held on each side of a frame
    uint64_t memory_limit_mb = 0;    ///< --memory-limit (0: physical memory)
};

/// What `options` says of reading a frame.
FrameReading frame_reading(const Options& options);

/// Maps `path` (maybe a frame pattern) to frame `frame`'s file.
std::string path_for_frame(const std::string& path, std::optional<int> frame);

/// Reads frame `frame` (nullopt: the single input image) as `reading`
/// says: the input, its beauty and every guide of `reading.roles` (within
/// the memory limit). Throws RunError naming the file.
std::unique_ptr<FrameInputs> read_frame_inputs(const FrameReading& reading, std::optional<int> frame,
                                               RunStats& stats);

}  // namespace mcdtool
