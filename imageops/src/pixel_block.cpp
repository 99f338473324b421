// pixel_block.cpp: loading image pixels into contiguous float blocks.
#include "pixel_block.h"

#include <cmath>

namespace mcdenoise {

using OIIO::ImageBuf;
using OIIO::ROI;
using OIIO::TypeDesc;

namespace {

bool can_view_in_place(const ImageBuf& img, const ROI& region)
{
    const OIIO::ImageSpec& spec = img.spec();
    return img.localpixels() && spec.format == TypeDesc::FLOAT
           && region.chbegin == 0 && region.chend == spec.nchannels
           && img.pixel_stride() == std::ptrdiff_t(sizeof(float)) * spec.nchannels
           && img.scanline_stride() % std::ptrdiff_t(sizeof(float)) == 0;
}

}  // namespace

bool load_block(const ImageBuf& img, ROI region, PixelBlock& block)
{
    block.region    = region;
    block.nchannels = region.nchannels();
    block.owned.clear();
    if (can_view_in_place(img, region)) {
        block.row_stride = img.scanline_stride() / std::ptrdiff_t(sizeof(float));
        block.data = static_cast<const float*>(
            img.pixeladdr(region.xbegin, region.ybegin));
        return true;
    }
    block.row_stride = std::ptrdiff_t(region.width()) * block.nchannels;
    block.owned.resize(size_t(block.row_stride) * region.height());
    block.data = block.owned.data();
    return img.get_pixels(region, TypeDesc::FLOAT, block.owned.data());
}

bool has_nonfinite(const PixelBlock& block)
{
    const std::ptrdiff_t n = std::ptrdiff_t(block.width()) * block.nchannels;
    for (int y = block.region.ybegin; y < block.region.yend; ++y) {
        const float* row = block.row(y);
        bool bad         = false;
        for (std::ptrdiff_t i = 0; i < n; ++i)
            bad |= !std::isfinite(row[i]);
        if (bad)
            return true;
    }
    return false;
}

PixelBlock with_finite_mask(const PixelBlock& src)
{
    const int nc = src.nchannels;
    PixelBlock out;
    out.region     = src.region;
    out.nchannels  = 2 * nc;
    out.row_stride = std::ptrdiff_t(src.width()) * out.nchannels;
    out.owned.resize(size_t(out.row_stride) * src.height());
    out.data = out.owned.data();
    float* dst = out.owned.data();
    for (int y = src.region.ybegin; y < src.region.yend; ++y) {
        const float* row = src.row(y);
        for (int x = 0; x < src.width(); ++x, row += nc, dst += 2 * nc) {
            for (int c = 0; c < nc; ++c) {
                const bool finite = std::isfinite(row[c]);
                dst[c]      = finite ? row[c] : 0.0f;
                dst[nc + c] = finite ? 1.0f : 0.0f;
            }
        }
    }
    return out;
}

std::vector<float> channel_plane(const PixelBlock& src, int channel)
{
    const int w = src.width();
    std::vector<float> plane(size_t(w) * src.height());
    float* dst = plane.data();
    for (int y = src.region.ybegin; y < src.region.yend; ++y) {
        const float* row = src.row(y) + channel;
        for (int x = 0; x < w; ++x)
            *dst++ = row[std::ptrdiff_t(x) * src.nchannels];
    }
    return plane;
}

}  // namespace mcdenoise
