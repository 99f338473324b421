// separable_mean.cpp: separable sums divided by the weights that contributed.
#include "separable_mean.h"

#include <OpenImageIO/imagebufalgo_util.h>

namespace mcdenoise {

using OIIO::ImageBuf;
using OIIO::ROI;

namespace {

// The window weight of every pixel of one row of `strip` when every value is
// finite; rows whose clipped vertical span matches reuse the previous row.
class GeometricWeights {
public:
    GeometricWeights(const Kernel1D& kernel, const ROI& region, const ROI& strip)
        : m_kernel(kernel), m_region(region), m_strip(strip),
          m_row(size_t(strip.width()))
    {
    }
    const double* row(int y)
    {
        const int r     = m_kernel.radius;
        const int above = std::min(r, y - m_region.ybegin);
        const int below = std::min(r, m_region.yend - 1 - y);
        if (above != m_above || below != m_below) {
            for (int x = m_strip.xbegin; x < m_strip.xend; ++x)
                m_row[size_t(x - m_strip.xbegin)] = window_weight(m_kernel, x, y, m_region);
            m_above = above;
            m_below = below;
        }
        return m_row.data();
    }

private:
    const Kernel1D& m_kernel;
    ROI m_region, m_strip;
    std::vector<double> m_row;
    int m_above = -1, m_below = -1;
};

void mean_strip(const PixelBlock& block, bool masked, const Kernel1D& kernel,
                SumOrigin origin, const ROI& strip, ResultPixels& result)
{
    const int nc   = result.roi.nchannels();
    const int sumc = block.nchannels;
    const size_t w = size_t(strip.width());
    std::vector<double> sums(w * strip.height() * sumc);
    separable_sums(block, kernel, origin, strip, sums.data());
    GeometricWeights geometric(kernel, block.region, strip);
    int64_t empty = 0;
    for (int y = strip.ybegin; y < strip.yend; ++y) {
        const double* s = sums.data() + size_t(y - strip.ybegin) * w * sumc;
        const double* g = masked ? nullptr : geometric.row(y);
        float* out      = result.pixel(strip.xbegin, y);
        for (size_t x = 0; x < w; ++x, s += sumc, out += nc) {
            for (int c = 0; c < nc; ++c) {
                const double weight = masked ? s[nc + c] : g[x];
                const bool any      = weight > 0.0;
                out[c]              = any ? float(s[c] / weight) : 0.0f;
                empty += !any;
            }
        }
    }
    result.empty_windows += empty;
}

}  // namespace

bool separable_mean(const char* op, ImageBuf& dst, const ImageBuf& beauty,
                    const Kernel1D& kernel, int nthreads, ResultPixels& result)
{
    const ROI bounds = beauty.roi();
    PixelBlock block;
    ROI region   = separable_source_region(result.roi, kernel, bounds);
    region.chbegin = result.roi.chbegin;
    region.chend   = result.roi.chend;
    if (!load_block(beauty, region, block)) {
        dst.errorfmt("{}: could not read the beauty pixels: {}", op, beauty.geterror());
        return false;
    }
    const bool masked = has_nonfinite(block);
    PixelBlock with_mask;
    if (masked)
        with_mask = with_finite_mask(block);
    const PixelBlock& source = masked ? with_mask : block;
    const SumOrigin origin { bounds.xbegin, bounds.ybegin };
    OIIO::ImageBufAlgo::parallel_image(result.roi, nthreads, [&](ROI strip) {
        mean_strip(source, masked, kernel, origin, strip, result);
    });
    return true;
}

}  // namespace mcdenoise
