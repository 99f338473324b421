// operation.cpp: ROI checks and result write-out shared by every operation.
#include "core/operation.h"

#include "core/window.h"

#include <OpenImageIO/imagebufalgo_util.h>

namespace mcdenoise {

using OIIO::ImageBuf;
using OIIO::ROI;

bool resolve_roi(const char* op, ImageBuf& dst, const ImageBuf& beauty, ROI& roi)
{
    if (!beauty.initialized()) {
        dst.errorfmt("{}: the beauty image is empty or unreadable{}{}", op,
                     beauty.has_error() ? ": " : "", beauty.geterror(false));
        return false;
    }
    if (beauty.deep() || beauty.spec().depth > 1) {
        dst.errorfmt("{}: deep and volume images are not supported", op);
        return false;
    }
    const ROI dw = beauty.roi();
    if (!roi.defined())
        roi = dw;
    roi.chend = std::min(roi.chend, dw.chend);
    if (roi.chbegin < 0 || roi.chbegin >= roi.chend) {
        dst.errorfmt("{}: ROI channels [{}, {}) select none of the beauty's {} channels",
                     op, roi.chbegin, roi.chend, dw.nchannels());
        return false;
    }
    if (roi.xbegin < dw.xbegin || roi.xend > dw.xend || roi.ybegin < dw.ybegin
        || roi.yend > dw.yend || roi.xbegin >= roi.xend || roi.ybegin >= roi.yend
        || roi.zbegin != dw.zbegin || roi.zend != dw.zend) {
        dst.errorfmt("{}: ROI x [{}, {}) y [{}, {}) is empty or outside the beauty's "
                     "data window x [{}, {}) y [{}, {})",
                     op, roi.xbegin, roi.xend, roi.ybegin, roi.yend, dw.xbegin, dw.xend,
                     dw.ybegin, dw.yend);
        return false;
    }
    return true;
}

bool check_window_op(const char* op, ImageBuf& dst, const ImageBuf& beauty, int size,
                     ROI& roi)
{
    const std::string problem = check_window_size(size);
    if (!problem.empty()) {
        dst.errorfmt("{}: {}", op, problem);
        return false;
    }
    return resolve_roi(op, dst, beauty, roi);
}

namespace {

// Allocate `dst` as IBAprep would (beauty's spec and metadata, float pixels,
// data window `roi`, channels 0 .. roi.chend) without clearing pixels that
// are about to be written.
void allocate_like(ImageBuf& dst, const ImageBuf& beauty, const ROI& roi)
{
    OIIO::ImageSpec spec = beauty.spec();
    spec.set_format(OIIO::TypeDesc::FLOAT);
    spec.channelformats.clear();
    spec.x      = roi.xbegin;
    spec.y      = roi.ybegin;
    spec.width  = roi.width();
    spec.height = roi.height();
    spec.nchannels = roi.chend;
    spec.channelnames.resize(size_t(roi.chend));
    if (spec.alpha_channel >= roi.chend)
        spec.alpha_channel = -1;
    if (spec.z_channel >= roi.chend)
        spec.z_channel = -1;
    dst.reset(spec, OIIO::InitializePixels::No);
}

}  // namespace

bool begin_result(const char* op, ImageBuf& dst, const ImageBuf& beauty,
                  std::initializer_list<const ImageBuf*> inputs, const ROI& roi,
                  ResultPixels& result)
{
    if (!dst.initialized())
        allocate_like(dst, beauty, roi);
    ROI r = roi;
    if (!OIIO::ImageBufAlgo::IBAprep(r, &dst, &beauty,
                                     OIIO::ImageBufAlgo::IBAprep_DST_FLOAT_PIXELS
                                         | OIIO::ImageBufAlgo::IBAprep_NO_SUPPORT_VOLUME)) {
        if (!dst.has_error())
            dst.errorfmt("{}: could not allocate the result", op);
        return false;
    }
    result.roi = roi;
    bool shared = false;
    for (const ImageBuf* in : inputs)
        shared |= in
                  && (in == &dst
                      || (in->localpixels() && in->localpixels() == dst.localpixels()));
    const bool direct = !shared && dst.localpixels()
                        && dst.spec().format == OIIO::TypeDesc::FLOAT
                        && roi.chend <= dst.nchannels();
    if (direct) {
        result.m_base = static_cast<float*>(dst.pixeladdr(roi.xbegin, roi.ybegin, roi.zbegin,
                                                          roi.chbegin));
        result.m_pixel_stride = dst.pixel_stride() / std::ptrdiff_t(sizeof(float));
        result.m_row_stride   = dst.scanline_stride() / std::ptrdiff_t(sizeof(float));
    } else {
        result.use_buffer(roi);
    }
    return true;
}

void ResultPixels::use_buffer(const ROI& r)
{
    roi            = r;
    m_pixel_stride = r.nchannels();
    m_row_stride   = std::ptrdiff_t(r.width()) * r.nchannels();
    m_buffer.reset(new float[size_t(m_row_stride) * r.height()]);
    m_base = m_buffer.get();
}

bool finish_result(const char* op, ImageBuf& dst, ResultPixels& result)
{
    if (result.m_buffer
        && !dst.set_pixels(result.roi, OIIO::TypeDesc::FLOAT, result.m_buffer.get())) {
        if (!dst.has_error())
            dst.errorfmt("{}: could not write the result pixels", op);
        return false;
    }
    const int64_t empty = result.empty_windows.load();
    if (empty > 0)
        dst.specmod().attribute("mcdenoise:empty_windows",
                                int(std::min<int64_t>(empty, INT32_MAX)));
    else
        dst.specmod().erase_attribute("mcdenoise:empty_windows");
    return true;
}

}  // namespace mcdenoise
