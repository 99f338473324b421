// pixel_block.cpp: loading image pixels into contiguous float blocks, and the
// derived blocks the filters read (finite masks, channel planes).
#include "core/pixel_block.h"

#include "core/window.h"

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

// 1 if the exponent field of `v` is at least `exponent_bits` (shifted into
// place), else 0; a form the compiler vectorises.
inline uint32_t exponent_at_least(float v, uint32_t exponent_bits)
{
    uint32_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    return (bits & 0x7f800000u) >= exponent_bits;
}

// True if any value of `block` has an exponent field of at least
// `exponent_bits`.
bool any_exponent_at_least(const PixelBlock& block, uint32_t exponent_bits, int nthreads)
{
    const std::ptrdiff_t n = std::ptrdiff_t(block.width()) * block.nchannels;
    std::atomic<bool> found { false };
    parallel_rows(block.region, nthreads, [&](int y) {
        const float* row = block.row(y);
        uint32_t hit     = 0;
        for (std::ptrdiff_t i = 0; i < n; ++i)
            hit |= exponent_at_least(row[i], exponent_bits);
        if (hit)
            found = true;
    });
    return found;
}

// An owned block with `nchannels` channels over `region`.
PixelBlock owned_block(const ROI& region, int nchannels)
{
    PixelBlock out;
    out.region     = region;
    out.nchannels  = nchannels;
    out.row_stride = std::ptrdiff_t(region.width()) * nchannels;
    out.owned.resize(plane_size(region) * size_t(nchannels));
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
    return any_exponent_at_least(block, 0x7f800000u, nthreads);
}

bool needs_finite_mask(const PixelBlock& block, int nthreads)
{
    static_assert(max_summed_magnitude == 0x1p100f, "the exponent below is 2^100's");
    return any_exponent_at_least(block, uint32_t(127 + 100) << 23, nthreads);
}

PixelBlock with_finite_mask(const PixelBlock& src, int nthreads)
{
    const int nc   = src.nchannels;
    PixelBlock out = owned_block(src.region, 2 * nc);
    parallel_rows(src.region, nthreads, [&](int y) {
        const float* in = src.row(y);
        float* dst      = out.owned_row(y);
        for (int c = 0; c < nc; ++c)
            masked_values(in + c, nc, src.width(), dst + c, dst + nc + c, 2 * nc);
    });
    return out;
}

PixelBlock nonfinite_indicator(const PixelBlock& src, int nthreads)
{
    PixelBlock out = owned_block(src.region, src.nchannels);
    parallel_rows(src.region, nthreads, [&](int y) {
        const float* in = src.row(y);
        float* dst      = out.owned_row(y);
        for (std::ptrdiff_t i = 0; i < out.row_stride; ++i)
            dst[i] = std::isfinite(in[i]) ? 0.0f : 1.0f;
    });
    return out;
}

Planes<float> channel_planes(const PixelBlock& src, int nthreads)
{
    const int w = src.width(), nc = src.nchannels;
    Planes<float> planes(src.region, nc);
    parallel_rows(src.region, nthreads, [&](int y) {
        const float* in = src.row(y);
        for (int c = 0; c < nc; ++c) {
            float* dst = planes.row(c, y);
            for (int x = 0; x < w; ++x)
                dst[x] = in[std::ptrdiff_t(x) * nc + c];
        }
    });
    return planes;
}

}  // namespace mcdenoise
