// pixel_block.cpp: loading image pixels into contiguous float blocks, and the
// derived blocks the filters read (finite masks, channel planes).
#include "pixel_block.h"

#include "window.h"

#include <OpenImageIO/imagebufalgo_util.h>

#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace mcdenoise {

using OIIO::ImageBuf;
using OIIO::ROI;
using OIIO::TypeDesc;

namespace {

bool can_view_in_place(const ImageBuf& img, const ROI& region)
{
    const OIIO::ImageSpec& spec = img.spec();
    const ROI dw = img.roi();
    return img.localpixels() && spec.format == TypeDesc::FLOAT
           && region.xbegin >= dw.xbegin && region.xend <= dw.xend
           && region.ybegin >= dw.ybegin && region.yend <= dw.yend
           && region.zbegin >= dw.zbegin && region.zend <= dw.zend
           && region.chbegin == 0 && region.chend == spec.nchannels
           && img.pixel_stride() == std::ptrdiff_t(sizeof(float)) * spec.nchannels
           && img.scanline_stride() % std::ptrdiff_t(sizeof(float)) == 0;
}

// 1 if `v` is NaN or infinite (all exponent bits set), else 0; a form the
// compiler vectorises.
inline uint32_t is_nonfinite_bits(float v)
{
    uint32_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    return (bits & 0x7f800000u) == 0x7f800000u;
}

// An owned block with `nchannels` channels over `region`.
PixelBlock owned_block(const ROI& region, int nchannels)
{
    PixelBlock out;
    out.region     = region;
    out.nchannels  = nchannels;
    out.row_stride = std::ptrdiff_t(region.width()) * nchannels;
    out.owned.resize(size_t(out.row_stride) * region.height());
    out.data = out.owned.data();
    return out;
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
    block = owned_block(region, region.nchannels());
    return img.get_pixels(region, TypeDesc::FLOAT, block.owned.data());
}

bool read_beauty(const char* op, ImageBuf& dst, const ImageBuf& beauty, const ROI& region,
                 PixelBlock& block)
{
    if (load_block(beauty, region, block))
        return true;
    dst.errorfmt("{}: could not read the beauty pixels: {}", op, beauty.geterror());
    return false;
}

bool has_nonfinite(const PixelBlock& block, int nthreads)
{
    const std::ptrdiff_t n = std::ptrdiff_t(block.width()) * block.nchannels;
    std::atomic<bool> found { false };
    parallel_rows(block.region, nthreads, [&](int y) {
        const float* row = block.row(y);
        uint32_t bad     = 0;
        for (std::ptrdiff_t i = 0; i < n; ++i)
            bad |= is_nonfinite_bits(row[i]);
        if (bad)
            found = true;
    });
    return found;
}

PixelBlock with_finite_mask(const PixelBlock& src, int nthreads)
{
    const int nc   = src.nchannels;
    PixelBlock out = owned_block(src.region, 2 * nc);
    parallel_rows(src.region, nthreads, [&](int y) {
        const float* in = src.row(y);
        float* dst = out.owned.data() + size_t(y - src.region.ybegin) * out.row_stride;
        for (int x = 0; x < src.width(); ++x, in += nc, dst += 2 * nc)
            for (int c = 0; c < nc; ++c) {
                const bool finite = std::isfinite(in[c]);
                dst[c]      = finite ? in[c] : 0.0f;
                dst[nc + c] = finite ? 1.0f : 0.0f;
            }
    });
    return out;
}

PixelBlock nonfinite_indicator(const PixelBlock& src, int nthreads)
{
    PixelBlock out = owned_block(src.region, src.nchannels);
    parallel_rows(src.region, nthreads, [&](int y) {
        const float* in = src.row(y);
        float* dst = out.owned.data() + size_t(y - src.region.ybegin) * out.row_stride;
        for (std::ptrdiff_t i = 0; i < out.row_stride; ++i)
            dst[i] = std::isfinite(in[i]) ? 0.0f : 1.0f;
    });
    return out;
}

std::vector<std::unique_ptr<float[]>> channel_planes(const PixelBlock& src, int nthreads)
{
    const int w = src.width(), nc = src.nchannels;
    std::vector<std::unique_ptr<float[]>> planes;
    for (int c = 0; c < nc; ++c)
        planes.emplace_back(new float[size_t(w) * src.height()]);
    parallel_rows(src.region, nthreads, [&](int y) {
        const float* in     = src.row(y);
        const size_t offset = size_t(y - src.region.ybegin) * w;
        for (int c = 0; c < nc; ++c) {
            float* dst = planes[size_t(c)].get() + offset;
            for (int x = 0; x < w; ++x)
                dst[x] = in[std::ptrdiff_t(x) * nc + c];
        }
    });
    return planes;
}

}  // namespace mcdenoise
