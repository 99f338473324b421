// compare.h: --compare REF, the result judged against a reference render
// with the library's metrics (relMSE, MSE, PSNR, SSIM), printed for the
// input and for the result so the gain is visible.
#pragma once

#include "input.h"

#include <OpenImageIO/imagebuf.h>

#include <string>
#include <string_view>

namespace mcdtool {

/// The reference's beauty channels (discovered like the input's, or chosen
/// by `beauty_channels`, --beauty, when not empty), as float. Throws
/// RunError naming `path`, also when it has not `input_beauty_channels`
/// beauty channels like the input.
ImageBuf reference_beauty(const std::string& path, std::string_view beauty_channels, ImageFiles& files,
                          size_t input_beauty_channels);

/// Prints the metrics of `before` and `after` against `reference` on
/// stdout, computed on `nthreads` threads (0: all). Throws RunError
/// "--compare : <library message>".
void print_comparison(const std::string& path, const ImageBuf& before, const ImageBuf& after,
                      const ImageBuf& reference, int nthreads);

}  // namespace mcdtool
