// guides.h: assembling the guide images of one frame: those discovered in
// the input beside the beauty, then the --aov files (which win), each
// checked for its channel count, the beauty's display window and covering
// the beauty's data window; a constant id guide is warned about.
#pragma once

#include "channels.h"
#include "commands.h"
#include "input.h"
#include "options.h"

#include <functional>
#include <string>

namespace mcdtool {

/// Maps a path as typed (maybe a frame pattern) to this frame's file.
using PathForFrame = std::function<std::string(const std::string&)>;

/// The guides of one frame: every --aov file, and each guide discovered in
/// `input` that a command of `options.steps` needs or uses (the others only
/// get a source, for -v).
Guides load_guides(const ImageBuf& input, const std::string& input_path, const Discovery& found,
                   const Options& options, const PathForFrame& frame_path_of, ImageFiles& files);

/// Throws RunError unless `guides` holds every role `command` needs; the
/// message names the command, the role and where it was looked for.
void require_guides(const Command& command, const Guides& guides, const std::string& input_path,
                    const ImageSpec& input_spec, const Discovery& found);

/// Throws RunError "<context> : ..." unless `guide`'s data window covers
/// `beauty`'s.
void require_coverage(const ImageBuf& guide, const ImageBuf& beauty, const std::string& context);

}  // namespace mcdtool
