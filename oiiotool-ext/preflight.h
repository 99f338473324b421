// preflight.h: the checks of the command line's values made once, before
// any frame is read: those that need no file (the OCIO display and view of
// --preview) and those that need only a header (the --beauty and --aov
// channel selectors, against the first frame's files). Command parameter
// ranges are checked by the parser itself (args.cpp), the rules between a
// command's parameters by the library on a 1x1 image. A failure is a
// UsageError: exit 2, reported once rather than once per frame.
#pragma once

#include "options.h"

#include <optional>
#include <string>
#include <vector>

namespace mcdtool {

/// The frames a run takes: those of `frame_list` (--frames), or nullopt for
/// the single input image when it is empty.
std::vector<std::optional<int>> frames_to_run(const std::string& frame_list);

/// Throws UsageError naming the option unless every argument value that
/// can be checked before reading pixels holds. Headers are read from the
/// first frame whose input exists (none: the frames report their errors).
void check_arguments(const Options& options);

}  // namespace mcdtool
