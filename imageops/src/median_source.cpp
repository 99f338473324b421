// median_source.cpp: reading the beauty into the planes the median walker uses.
#include "median_walker.h"

#include "separable_sum.h"

#include <OpenImageIO/imagebufalgo_util.h>

#include <cmath>

namespace mcdenoise {

using OIIO::ImageBuf;
using OIIO::ROI;

namespace {

// Per channel, 1 for each ROI pixel whose window holds only finite values:
// box sums of a non-finite indicator, which are exact small integers.
std::vector<std::vector<char>> finite_window_flags(const PixelBlock& block,
                                                   const ROI& roi, int size)
{
    const int nc = block.nchannels;
    PixelBlock bad;
    bad.region     = block.region;
    bad.nchannels  = nc;
    bad.row_stride = std::ptrdiff_t(block.width()) * nc;
    bad.owned.resize(size_t(bad.row_stride) * block.height());
    bad.data = bad.owned.data();
    float* out = bad.owned.data();
    for (int y = block.region.ybegin; y < block.region.yend; ++y) {
        const float* row = block.row(y);
        for (std::ptrdiff_t i = 0; i < bad.row_stride; ++i)
            *out++ = std::isfinite(row[i]) ? 0.0f : 1.0f;
    }
    std::vector<double> counts(size_t(roi.width()) * roi.height() * nc);
    const Kernel1D box = box_kernel(size);
    separable_sums(bad, box, { block.region.xbegin, block.region.ybegin }, roi,
                   counts.data());
    std::vector<std::vector<char>> flags(size_t(nc),
                                         std::vector<char>(size_t(roi.width()) * roi.height()));
    for (size_t p = 0; p < flags[0].size(); ++p)
        for (int c = 0; c < nc; ++c)
            flags[size_t(c)][p] = counts[p * nc + size_t(c)] == 0.0;
    return flags;
}

}  // namespace

bool load_median_source(const char* op, ImageBuf& dst, const ImageBuf& beauty,
                        const ROI& roi, int size, MedianSource& source)
{
    source.radius = size / 2;
    source.roi    = roi;
    source.region = grow_and_clip(roi, source.radius, beauty.roi());
    source.region.chbegin = roi.chbegin;
    source.region.chend   = roi.chend;
    PixelBlock block;
    if (!load_block(beauty, source.region, block)) {
        dst.errorfmt("{}: could not read the beauty pixels: {}", op, beauty.geterror());
        return false;
    }
    source.planes.clear();
    for (int c = 0; c < block.nchannels; ++c)
        source.planes.push_back(channel_plane(block, c));
    source.window_finite.clear();
    if (has_nonfinite(block))
        source.window_finite = finite_window_flags(block, roi, size);
    return true;
}

}  // namespace mcdenoise
