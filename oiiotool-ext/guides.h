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
#include <set>
#include <string>
#include <vector>

namespace mcdtool {

/// Maps a path as typed (maybe a frame pattern) to this frame's file.
using PathForFrame = std::function<std::string(const std::string&)>;

/// The guide roles the commands of `steps` need or use when present, and
/// the motion guide when the frames are denoised `across_frames` (--temporal).
std::set<Role> roles_used(const std::vector<Step>& steps, bool across_frames);

/// The guides of one frame: every --aov file of `aovs`, and each guide
/// discovered in `input` whose role is in `used` (the others only get a
/// source, for -v).
GuideImages load_guides(const ImageBuf& input, const std::string& input_path, const Discovery& found,
                   const std::vector<AovRequest>& aovs, const std::set<Role>& used,
                   const PathForFrame& frame_path_of, ImageFiles& files);

/// Throws RunError unless `guides` holds every role `command` needs; the
/// message names the command, the role and where it was looked for.
void require_guides(const Command& command, const GuideImages& guides, const std::string& input_path,
                    const ImageSpec& input_spec, const Discovery& found);

/// Throws RunError "<context> : ..." unless `guide`'s data window covers
/// `beauty`'s.
void require_coverage(const ImageBuf& guide, const ImageBuf& beauty, const std::string& context);

}  // namespace mcdtool
