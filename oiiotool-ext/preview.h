// preview.h: --preview, a display-referred side-by-side picture (input |
// result, and | reference with --compare) through OpenColorIO: the config
// of --ocio-config or $OCIO with its display and view, else a plain
// linear -> sRGB transform.
#pragma once

#include "options.h"
#include "output.h"

#include <OpenImageIO/imagebuf.h>

#include <string>

namespace mcdtool {

/// Throws RunError unless the OCIO config (--ocio-config or $OCIO) loads
/// and has the display and view --preview would use (--display, --view).
void check_display(const DisplayChoice& choice);

/// Adds the preview of `before` | `after` (| `reference` if not null) to
/// `batch` at `path`, as 8-bit display values through `choice`.
void write_preview(const std::string& path, const ImageBuf& before, const ImageBuf& after,
                   const ImageBuf* reference, const DisplayChoice& choice, OutputBatch& batch);

}  // namespace mcdtool
