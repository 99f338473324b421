// parts.h: multi-part OpenEXR files (Arnold, RenderMan and Nuke write the
// beauty and each AOV in a part of its own): every part read into one image
// whose channels are the parts' in order, named so that discovery finds the
// beauty and the guides across parts, and written back with the same parts,
// part names, channel names and per-part compression and pixel types.
#pragma once

#include "output.h"

#include <OpenImageIO/imagebuf.h>

#include <string>
#include <vector>

namespace mcdtool {

/// One part of a multi-part file.
struct Part {
    ImageSpec spec;   ///< as stored: its name, channels, types, compression
    int chbegin = 0;  ///< its first channel in the merged image
};

/// The parts of `path` (from the headers), or none when it has a single
/// part or cannot be read. Throws RunError "<context> : ..." when the parts'
/// windows differ, a part is deep, or two channels would share a name.
std::vector<Part> file_parts(const std::string& path, std::string_view context);

/// The merged spec of `parts`: the first part's windows and metadata, every
/// part's channels as float. A channel keeps its name in the first part or
/// when it has a layer ("diffuse.R"); otherwise the part name goes before
/// it ("R" in part "diffuse" is "diffuse.R").
ImageSpec merged_spec(const std::vector<Part>& parts);

/// Every part of `path` read as float into one image of `merged_spec`.
/// Throws RunError naming the file and the part.
ImageBuf read_parts(const std::string& path, const std::vector<Part>& parts, std::string_view context);

/// True if `path`'s format can hold several parts (OpenEXR).
bool writes_parts(const std::string& path);

/// Writes `pixels` (a merged image of `parts`) to `path` as those parts,
/// with `format` (-d, --compression) applied to each.
void write_parts(OutputBatch& batch, const std::string& path, const std::vector<Part>& parts,
                 const ImageBuf& pixels, const OutputFormat& format, const std::string& context);

}  // namespace mcdtool
