// operation.cpp: ROI checks and result write-out shared by every operation.
#include "operation.h"

#include "window.h"

#include <OpenImageIO/imagebufalgo_util.h>

namespace mcdenoise {

using OIIO::ImageBuf;
using OIIO::ROI;

ResultPixels::ResultPixels(const ROI& r)
    : roi(r), data(size_t(r.width()) * r.height() * r.nchannels(), 0.0f)
{
}

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

bool write_result(const char* op, ImageBuf& dst, const ImageBuf& beauty,
                  const ResultPixels& result)
{
    ROI roi = result.roi;
    if (!OIIO::ImageBufAlgo::IBAprep(roi, &dst, &beauty,
                                     OIIO::ImageBufAlgo::IBAprep_DST_FLOAT_PIXELS
                                         | OIIO::ImageBufAlgo::IBAprep_NO_SUPPORT_VOLUME))
        return false;
    if (!dst.set_pixels(result.roi, OIIO::TypeDesc::FLOAT, result.data.data())) {
        if (!dst.has_error())
            dst.errorfmt("{}: could not write the result pixels", op);
        return false;
    }
    const int64_t empty = result.empty_windows.load();
    if (empty > 0)
        dst.specmod().attribute("mcdenoise:empty_windows", int(std::min<int64_t>(empty, INT32_MAX)));
    else
        dst.specmod().erase_attribute("mcdenoise:empty_windows");
    return true;
}

}  // namespace mcdenoise
