// simple.h: the report's simple filters, guided by the beauty alone:
// box mean, median and binomial ("Pascal's triangle") gaussian.
#pragma once

#include <mcdenoise/defaults.h>
#include <mcdenoise/export.h>

#include <OpenImageIO/imagebuf.h>

MCDENOISE_API_BEGIN

using OIIO::ImageBuf;
using OIIO::ROI;

/// The largest window side any filter accepts.
constexpr int max_window_size = 255;


/// Box mean: every pixel becomes the mean of the finite values in the
/// `size` x `size` window around it (clipped to the data window). Cost is
/// independent of `size` (sliding sums).
ImageBuf mean(const ImageBuf& beauty, int size = default_window_size, ROI roi = {},
              int nthreads = 0);
/// Write to an existing image `dst` (allocating if it is uninitialized).
bool mean(ImageBuf& dst, const ImageBuf& beauty, int size = default_window_size, ROI roi = {},
          int nthreads = 0);

/// Median: every pixel becomes, per channel, the median of the finite
/// values in the `size` x `size` window around it; for an even count, the
/// mean of the two middle values. Fixed-size interior windows use SIMD
/// selection networks; clipped windows and windows with non-finite values
/// select among the values that are there.
ImageBuf median(const ImageBuf& beauty, int size = default_window_size, ROI roi = {},
                int nthreads = 0);
/// Write to an existing image `dst` (allocating if it is uninitialized).
bool median(ImageBuf& dst, const ImageBuf& beauty, int size = default_window_size, ROI roi = {},
            int nthreads = 0);

/// Binomial gaussian: the weighted mean of the finite values in the window,
/// with weight C(k-1, dx+r) * C(k-1, dy+r) for window side k = `size`,
/// radius r and offsets dx, dy in [-r, r] (a row of Pascal's triangle on
/// each axis), normalised by the weights that contributed.
ImageBuf gaussian(const ImageBuf& beauty, int size = default_window_size, ROI roi = {},
                  int nthreads = 0);
/// Write to an existing image `dst` (allocating if it is uninitialized).
bool gaussian(ImageBuf& dst, const ImageBuf& beauty, int size = default_window_size,
              ROI roi = {}, int nthreads = 0);

MCDENOISE_API_END
