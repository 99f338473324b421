// median_source.cpp: reading the beauty into the planes the median walker uses.
#include "walkers/median_walker.h"

#include "walkers/separable_mean.h"

#include <OpenImageIO/imagebufalgo_util.h>

#include <cmath>

namespace mcdenoise {

using OIIO::ImageBuf;
using OIIO::ROI;

namespace {

// The box mean of a non-finite indicator over every ROI pixel's window:
// exactly 0 where the window holds only finite values. Its sums are small
// integers, exact from any restart point, so they restart from the block's
// own corner.
std::unique_ptr<ResultPixels> nonfinite_share(const PixelBlock& block, const ROI& roi,
                                              int size, int nthreads)
{
    SeparableSource indicator;
    make_separable_source(nonfinite_indicator(block, nthreads), block.region,
                          box_kernel(size), nthreads, indicator);
    auto share = std::make_unique<ResultPixels>();
    share->use_buffer(roi);
    OIIO::ImageBufAlgo::parallel_image(roi, nthreads, [&](ROI strip) {
        separable_mean_strip(indicator, strip, *share);
    });
    return share;
}

}  // namespace

bool load_median_source(const char* op, ImageBuf& dst, const ImageBuf& beauty,
                        const ROI& roi, int size, int nthreads, MedianSource& source)
{
    source.radius  = size / 2;
    source.roi     = roi;
    ROI region     = grow_and_clip(roi, source.radius, beauty.roi());
    region.chbegin = roi.chbegin;
    region.chend   = roi.chend;
    PixelBlock block;
    if (!read_beauty(op, dst, beauty, region, block))
        return false;
    source.planes = channel_planes(block, nthreads);
    source.nonfinite_share.reset();
    if (has_nonfinite(block, nthreads))
        source.nonfinite_share = nonfinite_share(block, roi, size, nthreads);
    return true;
}

}  // namespace mcdenoise
