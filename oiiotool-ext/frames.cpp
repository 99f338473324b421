// frames.cpp: frame patterns and frame lists.
#include "frames.h"

#include "error.h"

#include <OpenImageIO/strutil.h>


namespace mcdtool {

using OIIO::Strutil::fmt::format;

namespace {

/// Digits of a lone '#' (oiiotool's convention).
constexpr int lone_hash_digits = 4;
/// More frames than this in one --frames list is surely a typo.
constexpr long max_frames = 1000000;
/// Digits a frame number may have (keeps every value inside an int).
constexpr size_t max_frame_digits = 9;

/// Where a frame pattern sits in a path, and how many digits it asks for.
struct PatternSpan {
    size_t begin = std::string::npos;
    size_t length = 0;
    int digits = 0;
};

/// Length of the run of `ch` starting at `at` in `text`.
size_t run_length(std::string_view text, size_t at, char ch)
{
    size_t end = at;
    while (end < text.size() && text[end] == ch)
        ++end;
    return end - at;
}

/// Length of the decimal digits starting at `at` in `text`.
size_t digit_count(std::string_view text, size_t at)
{
    size_t end = at;
    while (end < text.size() && text[end] >= '0' && text[end] <= '9')
        ++end;
    return end - at;
}

/// Finds the first frame pattern in `path`: a run of '#', a run of '@', or
/// '%' [0] [digits] 'd'.
PatternSpan find_pattern(std::string_view path)
{
    PatternSpan span;
    for (size_t at = 0; at < path.size(); ++at) {
        char ch = path[at];
        if (ch == '#' || ch == '@') {
            size_t length = run_length(path, at, ch);
            int digits = ch == '#' && length == 1 ? lone_hash_digits : int(length);
            return PatternSpan{ at, length, digits };
        }
        if (ch != '%')
            continue;
        size_t width_at = at + 1 + (at + 1 < path.size() && path[at + 1] == '0' ? 1 : 0);
        size_t width_digits = digit_count(path, width_at);
        size_t d_at = width_at + width_digits;
        if (d_at < path.size() && path[d_at] == 'd' && width_digits <= 2) {
            int digits = width_digits ? std::stoi(std::string(path.substr(width_at, width_digits))) : 1;
            return PatternSpan{ at, d_at + 1 - at, digits };
        }
    }
    return span;
}

/// Reads an optionally negative integer of 1 to 9 digits at `at`, moving
/// `at` past it; false if there is none.
bool read_integer(std::string_view text, size_t& at, long& value)
{
    size_t start = at;
    bool negative = at < text.size() && text[at] == '-';
    size_t digits = digit_count(text, at + (negative ? 1 : 0));
    if (digits == 0 || digits > max_frame_digits)
        return false;
    at += (negative ? 1 : 0) + digits;
    value = std::stol(std::string(text.substr(start, at - start)));
    return true;
}

/// One part of a frame list: "7", "1-48" or "1-10x2" (also "10-1", "-5--1").
bool parse_range(std::string_view text, long& first, long& last, long& step)
{
    size_t at = 0;
    if (!read_integer(text, at, first))
        return false;
    last = first;
    step = 1;
    if (at == text.size())
        return true;
    if (text[at] != '-' || !read_integer(text, ++at, last))
        return false;
    if (at == text.size())
        return true;
    if (text[at] != 'x' || !read_integer(text, ++at, step) || step < 0)
        return false;
    return at == text.size();
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
    std::vector<int> frames;
    for (const std::string& part : OIIO::Strutil::splits(list, ",")) {
        std::string text(OIIO::Strutil::strip(part));
        long first = 0;
        long last = 0;
        long step = 0;
        if (!parse_range(text, first, last, step))
            throw UsageError(format("--frames : cannot read '{}' in '{}' (expected e.g. 1-48, 1-10x2, 1,3,5)",
                                    part, list));
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
