// compare.h: --compare REF, the result judged against a reference render
// with the library's metrics (relMSE, MSE, PSNR, SSIM), printed for the
// input and for the result so the gain is visible.
#pragma once

#include "input.h"
#include "options.h"

#include <OpenImageIO/imagebuf.h>

#include <string>

namespace mcdtool {

/// The reference's beauty channels (discovered like the input's, or chosen
/// by --beauty), as float. Throws RunError naming `path`, also when it has
/// not `beauty_channels` beauty channels like the input.
ImageBuf reference_beauty(const std::string& path, const Options& options, ImageFiles& files,
                          size_t beauty_channels);

/// Prints the metrics of `before` and `after` against `reference` on
/// stdout. Throws RunError "--compare : <library message>".
void print_comparison(const std::string& path, const ImageBuf& before, const ImageBuf& after,
                      const ImageBuf& reference, const Options& options);

}  // namespace mcdtool
