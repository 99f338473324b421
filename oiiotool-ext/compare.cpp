// compare.cpp: reading the reference and printing the metrics.
#include "compare.h"

#include "channels.h"
#include "error.h"

#include <mcdenoise/metrics.h>

#include <OpenImageIO/strutil.h>

#include <cstdio>

namespace mcdtool {

using OIIO::Strutil::fmt::format;

namespace {

/// One library call: every metric of `image` against `reference`.
mcdenoise::ImageComparison measure(const ImageBuf& image, const ImageBuf& reference, int nthreads)
{
    mcdenoise::ImageComparison metrics = mcdenoise::compare_images(image, reference, {}, nthreads);
    if (!metrics.ok)
        throw RunError(format("--compare : {}", one_line(metrics.error)));
    return metrics;
}

/// "relMSE 0.01234  MSE 0.000567  PSNR 32.47 dB  SSIM 0.9312".
std::string metrics_text(const mcdenoise::ImageComparison& m)
{
    std::string text = format("relMSE {:.6g}  MSE {:.6g}  PSNR {:.2f} dB  SSIM {:.4f}", m.rel_mse, m.mse,
                              m.psnr, m.ssim);
    if (m.nonfinite > 0)
        text += format("  ({} non-finite pixels left out)", m.nonfinite);
    return text;
}

/// "mean relMSE 0.0123  temporal error 0.456  flicker 0.0078" (or why not).
std::string sequence_text(const mcdenoise::SequenceComparison& s)
{
    if (!s.ok)
        return "no sequence figures: " + one_line(s.error);
    return format("mean relMSE {:.6g}  temporal error {:.6g}  flicker {:.6g}", s.mean_rel_mse, s.temporal_error,
                  s.flicker);
}

}  // namespace

void SequenceCompare::add(const ImageBuf& before, const ImageBuf& after, const ImageBuf& reference)
{
    mcdenoise::add_sequence_frame(input_, before, reference);
    mcdenoise::add_sequence_frame(result_, after, reference);
}

void SequenceCompare::print() const
{
    const mcdenoise::SequenceComparison input = mcdenoise::sequence_comparison(input_);
    const mcdenoise::SequenceComparison result = mcdenoise::sequence_comparison(result_);
    std::printf("mcdtool: compare sequence, %d frames in run order (flicker is meaningful for a static shot)\n"
                "  input   %s\n  result  %s\n", result.frames, sequence_text(input).c_str(),
                sequence_text(result).c_str());
}

ImageBuf reference_beauty(const std::string& path, std::string_view beauty_channels, ImageFiles& files,
                          size_t input_beauty_channels)
{
    const ImageBuf& reference = files.get(path, "--compare");
    Discovery found = discover_channels(reference.spec(), beauty_channels, path);
    if (found.beauty.size() != input_beauty_channels)
        throw RunError(format("--compare : the reference '{}' has {} beauty channel(s), the input has {}", path,
                              found.beauty.size(), input_beauty_channels));
    return extract_channels(reference, found.beauty);
}

void print_comparison(const std::string& path, const ImageBuf& before, const ImageBuf& after,
                      const ImageBuf& reference, int nthreads)
{
    std::string input_metrics = metrics_text(measure(before, reference, nthreads));
    std::string result_metrics = metrics_text(measure(after, reference, nthreads));
    std::printf("mcdtool: compare %s\n  input   %s\n  result  %s\n", path.c_str(), input_metrics.c_str(),
                result_metrics.c_str());
}

}  // namespace mcdtool
