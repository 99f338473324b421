// frames.h: frame-sequence patterns and frame lists, as a compositor types
// them: 'beauty.####.exr' (or '#', '@@@', '%04d') with --frames 1-48,
// 1-10x2 or 1,3,5.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace mcdtool {

/// True if `path` holds a frame pattern: a run of '#', a run of '@', or a
/// printf-style %d / %0Nd.
bool has_frame_pattern(std::string_view path);

/// `pattern` with its frame pattern replaced by `frame`. A lone '#' is four
/// digits (as in oiiotool); a run of N '#' or N '@' is N digits (as in
/// Nuke), so 'beauty.####.exr' gives 'beauty.0007.exr'. Without a pattern
/// the path is returned unchanged.
std::string frame_path(std::string_view pattern, int frame);

/// Parses "1-48", "1-10x2", "10-1", "1,3,5" or mixtures ("1-5,10,20-30x5");
/// throws UsageError naming the bad part.
std::vector<int> parse_frame_list(std::string_view list);

}  // namespace mcdtool
