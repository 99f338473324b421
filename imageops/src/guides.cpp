// guides.cpp: checking and normalising auxiliary buffers.
#include "guides.h"

#include <OpenImageIO/imagebufalgo_util.h>

#include <atomic>
#include <cmath>

namespace mcdenoise {

using OIIO::ImageBuf;
using OIIO::ROI;

bool check_guide(const char* op, const char* name, ImageBuf& dst, const ImageBuf& guide,
                 int nchannels, const ROI& roi)
{
    if (!guide.initialized()) {
        dst.errorfmt("{}: the {} image is empty or unreadable{}{}", op, name,
                     guide.has_error() ? ": " : "", guide.geterror(false));
        return false;
    }
    if (guide.nchannels() != nchannels) {
        dst.errorfmt("{}: {} has {} channel{}, expected {}", op, name, guide.nchannels(),
                     guide.nchannels() == 1 ? "" : "s", nchannels);
        return false;
    }
    const ROI dw = guide.roi();
    if (roi.xbegin < dw.xbegin || roi.xend > dw.xend || roi.ybegin < dw.ybegin
        || roi.yend > dw.yend) {
        dst.errorfmt("{}: {} data window x [{}, {}) y [{}, {}) does not cover the ROI "
                     "x [{}, {}) y [{}, {})",
                     op, name, dw.xbegin, dw.xend, dw.ybegin, dw.yend, roi.xbegin,
                     roi.xend, roi.ybegin, roi.yend);
        return false;
    }
    return true;
}

namespace {

// Reads `guide` over `region` as `Raw` values and maps each pixel through
// `convert(raw, inside)` (`inside`: within the guide's data window), strip
// by strip on `nthreads` threads.
template<class T, class Raw, class Convert>
bool load_plane(const char* op, ImageBuf& dst, const ImageBuf& guide, const ROI& region,
                int nthreads, OIIO::TypeDesc raw_type, GuidePlane<T>& plane,
                Convert&& convert)
{
    const int nc = guide.nchannels();
    const ROI dw = guide.roi();
    plane.region = region;
    plane.values.resize(size_t(region.width()) * region.height());
    std::atomic<bool> ok { true };
    ROI rows    = region;
    rows.chbegin = 0;
    rows.chend   = nc;
    OIIO::ImageBufAlgo::parallel_image(rows, nthreads, [&](ROI strip) {
        std::vector<Raw> raw(size_t(strip.width()) * strip.height() * nc);
        if (!guide.get_pixels(strip, raw_type, raw.data())) {
            ok = false;
            return;
        }
        const Raw* in = raw.data();
        for (int y = strip.ybegin; y < strip.yend; ++y)
            for (int x = strip.xbegin; x < strip.xend; ++x, in += nc)
                plane.values[plane.index(x, y)] = convert(in, dw.contains(x, y));
    });
    if (!ok) {
        dst.errorfmt("{}: could not read a guide: {}", op, guide.geterror());
        return false;
    }
    return true;
}

int64_t rounded_id(double v)
{
    constexpr double limit = 9.0e18;  // inside int64's range
    return int64_t(std::nearbyint(std::clamp(v, -limit, limit)));
}

}  // namespace

bool load_object_ids(const char* op, ImageBuf& dst, const ImageBuf& ids, const ROI& region,
                     int nthreads, IdPlane& plane)
{
    return load_plane<int64_t, double>(op, dst, ids, region, nthreads, OIIO::TypeDesc::DOUBLE,
                                       plane, [](const double* v, bool inside) {
                                           if (!inside)
                                               return no_guide_id;
                                           return std::isnan(*v) ? int64_t(-1) : rounded_id(*v);
                                       });
}

bool load_reflect_ids(const char* op, ImageBuf& dst, const ImageBuf& ids, const ROI& region,
                      int nthreads, IdPlane& plane)
{
    return load_plane<int64_t, double>(op, dst, ids, region, nthreads, OIIO::TypeDesc::DOUBLE,
                                       plane, [](const double* v, bool inside) {
                                           if (!inside)
                                               return no_guide_id;
                                           const int64_t id = std::isnan(*v) ? -1 : rounded_id(*v);
                                           return id < 0 ? int64_t(-1) : id;
                                       });
}

bool load_normals(const char* op, ImageBuf& dst, const ImageBuf& normals, const ROI& region,
                  int nthreads, GuidePlane<UnitNormal>& plane)
{
    return load_plane<UnitNormal, float>(
        op, dst, normals, region, nthreads, OIIO::TypeDesc::FLOAT, plane,
        [](const float* n, bool inside) {
            const double len = std::sqrt(double(n[0]) * n[0] + double(n[1]) * n[1]
                                         + double(n[2]) * n[2]);
            if (!inside || !(len > 0.0) || !std::isfinite(len))
                return UnitNormal {};
            return UnitNormal { float(n[0] / len), float(n[1] / len), float(n[2] / len) };
        });
}

bool load_depths(const char* op, ImageBuf& dst, const ImageBuf& depth, const ROI& region,
                 int nthreads, GuidePlane<float>& plane)
{
    return load_plane<float, float>(op, dst, depth, region, nthreads, OIIO::TypeDesc::FLOAT,
                                    plane, [](const float* d, bool inside) {
                                        const bool far = !inside || !std::isfinite(*d)
                                                         || *d >= infinitely_far;
                                        return far ? std::numeric_limits<float>::infinity()
                                                   : *d;
                                    });
}

}  // namespace mcdenoise
