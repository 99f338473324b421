// input.h: reading the input, guide and reference images, with one-line
// errors that name the file, and a per-frame cache so a file named twice
// (the input and --aov normal=render.exr:N) is read once.
#pragma once

#include "runstats.h"

#include <OpenImageIO/imagebuf.h>

#include <cstdint>
#include <map>
#include <string>
#include <string_view>

namespace mcdtool {

using OIIO::ImageBuf;

/// Reads all pixels of subimage 0 of `path` as float. Throws RunError
/// "<context> : cannot read '<path>': <reason>" for missing, unreadable or
/// truncated files, and before allocating anything when its float pixels
/// would exceed `memory_limit` bytes (memory_limit.h).
ImageBuf read_image(const std::string& path, std::string_view context, uint64_t memory_limit);

/// Warns on stderr ("<context> : ...") when `image` is 8-bit display-
/// referred (PNG, JPEG or an sRGB-tagged 8-bit file): the filters assume
/// linear light.
void warn_if_display_referred(const ImageBuf& image, std::string_view context);

/// True if the file `image` was read from stores channel `c` as integers
/// (which reading as float scaled to [0, 1]).
bool stored_as_integers(const ImageBuf& image, int c);

/// The channels of an image that its file stores as integers, by channel
/// index, each in that integer type (ids in an integer channel, such as
/// Arnold's ID pass, are the whole numbers stored).
using IntegerChannels = std::map<int, ImageBuf>;

/// The images read for one frame, by path.
class ImageFiles {
public:
    ImageFiles(RunStats& stats, uint64_t memory_limit) : stats_(stats), memory_limit_(memory_limit) {}
    /// The image at `path`, read on first use (timed as I/O).
    const ImageBuf& get(const std::string& path, std::string_view context);
    /// The channels the file of `image` (an image `get` returned) stores as
    /// integers, with `image`'s windows and metadata: read on first use,
    /// with one more opening of the file, then kept. Throws RunError naming
    /// the file.
    const IntegerChannels& integer_channels(const ImageBuf& image);

private:
    RunStats& stats_;
    uint64_t memory_limit_;
    std::map<std::string, ImageBuf> images_;
    std::map<const ImageBuf*, IntegerChannels> integers_;
};

}  // namespace mcdtool
