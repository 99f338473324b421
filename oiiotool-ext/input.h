// input.h: reading the input, guide and reference images, with one-line
// errors that name the file, and a per-frame cache so a file named twice
// (the input and --aov normal=render.exr:N) is read once.
#pragma once

#include "runstats.h"

#include <OpenImageIO/imagebuf.h>

#include <map>
#include <string>
#include <string_view>

namespace mcdtool {

using OIIO::ImageBuf;

/// Reads all pixels of subimage 0 of `path` as float. Throws RunError
/// "<context> : cannot read '<path>': <reason>" for missing, unreadable or
/// truncated files.
ImageBuf read_image(const std::string& path, std::string_view context);

/// The images read for one frame, by path.
class ImageFiles {
public:
    explicit ImageFiles(RunStats& stats) : stats_(stats) {}
    /// The image at `path`, read on first use (timed as I/O).
    const ImageBuf& get(const std::string& path, std::string_view context);

private:
    RunStats& stats_;
    std::map<std::string, ImageBuf> images_;
};

}  // namespace mcdtool
