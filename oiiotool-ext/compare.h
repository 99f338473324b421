// compare.h: --compare REF, the result judged against a reference render
// with the library's metrics (relMSE, MSE, PSNR, SSIM), printed for the
// input and for the result so the gain is visible; over a sequence, also
// the sequence figures (mean relMSE, temporal error, flicker) at the end.
#pragma once

#include "input.h"

#include <mcdenoise/sequence_metrics.h>

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

/// --compare over a sequence: the running figures of the input and of the
/// result against the references, frame by frame in run order.
class SequenceCompare {
public:
    explicit SequenceCompare(int nthreads)
        : input_(mcdenoise::start_sequence({}, nthreads)), result_(mcdenoise::start_sequence({}, nthreads))
    {
    }
    /// Adds the next frame compared (its input, result and reference beauty).
    void add(const ImageBuf& before, const ImageBuf& after, const ImageBuf& reference);
    /// Prints the sequence figures on stdout (or why there are none).
    void print() const;

private:
    mcdenoise::SequenceSums input_;
    mcdenoise::SequenceSums result_;
};

}  // namespace mcdtool
