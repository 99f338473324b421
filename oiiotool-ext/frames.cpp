// frames.cpp: frame patterns and frame lists.
#include "frames.h"

#include "error.h"

#include <OpenImageIO/strutil.h>

#include <regex>

namespace mcdtool {

using OIIO::Strutil::fmt::format;

namespace {

/// Digits of a lone '#' (oiiotool's convention).
constexpr int lone_hash_digits = 4;
/// More frames than this in one --frames list is surely a typo.
constexpr long max_frames = 1000000;

/// Where a frame pattern sits in a path, and how many digits it asks for.
struct PatternSpan {
    size_t begin = std::string::npos;
    size_t length = 0;
    int digits = 0;
};

/// Finds the first frame pattern in `path`.
PatternSpan find_pattern(std::string_view path)
{
    static const std::regex pattern_re("(#+)|(@+)|%(0?)([0-9]*)d");
    std::string text(path);
    std::smatch match;
    PatternSpan span;
    if (!std::regex_search(text, match, pattern_re))
        return span;
    span.begin = size_t(match.position(0));
    span.length = size_t(match.length(0));
    if (match[1].matched)
        span.digits = match.length(1) == 1 ? lone_hash_digits : int(match.length(1));
    else if (match[2].matched)
        span.digits = int(match.length(2));
    else
        span.digits = match[4].length() ? OIIO::Strutil::stoi(match[4].str()) : 1;
    return span;
}

}  // namespace

bool has_frame_pattern(std::string_view path)
{
    return find_pattern(path).begin != std::string::npos;
}

std::string frame_path(std::string_view pattern, int frame)
{
    PatternSpan span = find_pattern(pattern);
    if (span.begin == std::string::npos)
        return std::string(pattern);
    std::string number = std::to_string(frame < 0 ? -long(frame) : long(frame));
    if (int(number.size()) < span.digits)
        number.insert(0, size_t(span.digits) - number.size(), '0');
    if (frame < 0)
        number.insert(0, 1, '-');
    std::string path(pattern);
    return path.replace(span.begin, span.length, number);
}

std::vector<int> parse_frame_list(std::string_view list)
{
    static const std::regex part_re("(-?[0-9]{1,9})(?:-(-?[0-9]{1,9})(?:x([0-9]{1,9}))?)?");
    std::vector<int> frames;
    for (const std::string& part : OIIO::Strutil::splits(list, ",")) {
        std::smatch match;
        std::string text(OIIO::Strutil::strip(part));
        if (text.empty() || text.size() > 24 || !std::regex_match(text, match, part_re))
            throw UsageError(format("--frames : cannot read '{}' in '{}' (expected e.g. 1-48, 1-10x2, 1,3,5)",
                                    part, list));
        long first = std::stol(match[1].str());
        long last = match[2].matched ? std::stol(match[2].str()) : first;
        long step = match[3].matched ? std::stol(match[3].str()) : 1;
        if (step < 1)
            throw UsageError(format("--frames : step must be >= 1 in '{}'", part));
        long count = (last >= first ? last - first : first - last) / step + 1;
        if (count + long(frames.size()) > max_frames)
            throw UsageError(format("--frames : '{}' holds more than {} frames", list, max_frames));
        long direction = last >= first ? 1 : -1;
        for (long i = 0; i < count; ++i)
            frames.push_back(int(first + direction * step * i));
    }
    if (frames.empty())
        throw UsageError(format("--frames : no frames in '{}'", list));
    return frames;
}

}  // namespace mcdtool
