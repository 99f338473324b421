// guides.cpp: checking and normalising auxiliary buffers.
#include "core/guides.h"

#include "core/pixel_block.h"

#include <OpenImageIO/imagebufalgo_util.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

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

// Copies the `n` values of type T at `in` to `out` as double.
template<class T>
void widen(const unsigned char* in, size_t n, double* out)
{
    const T* v = reinterpret_cast<const T*>(in);
    std::copy(v, v + n, out);
}

// The values of `img` over `part` as double, integer pixel types as the
// whole numbers they store (OIIO's conversion would scale them to [0, 1]);
// `stored` is working memory.
bool get_stored_values(const ImageBuf& img, const ROI& part, double* out,
                       std::vector<unsigned char>& stored)
{
    using OIIO::TypeDesc;
    const TypeDesc t = img.spec().format;
    if (t.basetype == TypeDesc::HALF || t.is_floating_point())
        return img.get_pixels(part, TypeDesc::DOUBLE, out);
    const size_t n = size_t(part.npixels()) * part.nchannels();
    stored.resize(n * t.size());
    if (!img.get_pixels(part, t, stored.data()))
        return false;
    switch (t.basetype) {
    case TypeDesc::UINT8: widen<uint8_t>(stored.data(), n, out); return true;
    case TypeDesc::INT8: widen<int8_t>(stored.data(), n, out); return true;
    case TypeDesc::UINT16: widen<uint16_t>(stored.data(), n, out); return true;
    case TypeDesc::INT16: widen<int16_t>(stored.data(), n, out); return true;
    case TypeDesc::UINT32: widen<uint32_t>(stored.data(), n, out); return true;
    case TypeDesc::INT32: widen<int32_t>(stored.data(), n, out); return true;
    case TypeDesc::UINT64: widen<uint64_t>(stored.data(), n, out); return true;
    case TypeDesc::INT64: widen<int64_t>(stored.data(), n, out); return true;
    default: return img.get_pixels(part, TypeDesc::DOUBLE, out);
    }
}

// Reads `guide` over `region` as `Raw` values and maps them row piece by row
// piece through `convert(raw, nc, n, inside, first)` (n pixels of nc values,
// for the pixels [first, first + n) of `region` in row-major order;
// `inside`: within the guide's data window), strip by strip on `nthreads`
// threads, a few rows at a time so the raw values stay in cache. Float
// values are read in place where the guide holds them; double values are
// the stored ones (`get_stored_values`).
template<class Raw, class Convert>
bool load_rows(const char* op, ImageBuf& dst, const ImageBuf& guide, const ROI& region,
               int nthreads, Convert&& convert)
{
    constexpr size_t chunk_values = 16384;
    const int nc = guide.nchannels();
    const ROI dw = guide.roi();
    std::atomic<bool> ok { true };
    ROI rows    = region;
    rows.chbegin = 0;
    rows.chend   = nc;
    OIIO::ImageBufAlgo::parallel_image(rows, nthreads, [&](ROI strip) {
        const int chunk = std::max(1, int(chunk_values / (size_t(strip.width()) * nc)));
        std::vector<double> wide;
        std::vector<unsigned char> stored;
        PixelBlock block;
        for (int y0 = strip.ybegin; y0 < strip.yend && ok; y0 += chunk) {
            ROI part  = strip;
            part.ybegin = y0;
            part.yend   = std::min(strip.yend, y0 + chunk);
            const Raw* in = nullptr;
            std::ptrdiff_t row_stride = std::ptrdiff_t(part.width()) * nc;
            if constexpr (std::is_same_v<Raw, float>) {
                ok = ok && load_block(guide, part, block);
                in         = block.data;
                row_stride = block.row_stride;
            } else {
                wide.resize(size_t(part.npixels()) * nc);
                ok = ok && get_stored_values(guide, part, wide.data(), stored);
                in = wide.data();
            }
            if (!ok)
                return;
            for (int y = part.ybegin; y < part.yend; ++y, in += row_stride) {
                const size_t out = pixel_offset(region, part.xbegin, y);
                const bool row_inside = y >= dw.ybegin && y < dw.yend;
                const int x0
                    = row_inside ? std::clamp(dw.xbegin, part.xbegin, part.xend) : part.xend;
                const int x1 = row_inside ? std::clamp(dw.xend, x0, part.xend) : part.xend;
                const int before = x0 - part.xbegin, within = x1 - x0;
                convert(in, nc, before, false, out);
                convert(in + std::ptrdiff_t(before) * nc, nc, within, true, out + before);
                convert(in + std::ptrdiff_t(before + within) * nc, nc,
                        part.xend - x1, false, out + before + within);
            }
        }
    });
    if (!ok) {
        dst.errorfmt("{}: could not read a guide: {}", op, guide.geterror());
        return false;
    }
    return true;
}

// `load_rows` into `plane`, sized to `region`: `convert(raw, nc, n, inside,
// out)` writes n values from `out` on.
template<class T, class Raw, class Convert>
bool load_plane(const char* op, ImageBuf& dst, const ImageBuf& guide, const ROI& region,
                int nthreads, Plane<T>& plane, Convert&& convert)
{
    plane     = Plane<T>(region);
    T* values = plane.values.data();
    return load_rows<Raw>(op, dst, guide, region, nthreads,
                          [&convert, values](const Raw* in, int nc, int n, bool inside,
                                             size_t first) {
                              convert(in, nc, n, inside, values + first);
                          });
}

// Reads `ids` over `region` through `convert` (load_plane's row form) into
// `plane`: half and float ids as float, the others as double (integer pixel
// types as the whole numbers they store, not scaled to [0, 1]).
template<class T, class Convert>
bool load_raw_ids(const char* op, ImageBuf& dst, const ImageBuf& ids, const ROI& region,
                  int nthreads, Plane<T>& plane, Convert&& convert)
{
    using OIIO::TypeDesc;
    const TypeDesc::BASETYPE t = TypeDesc::BASETYPE(ids.spec().format.basetype);
    if (t == TypeDesc::HALF || t == TypeDesc::FLOAT)
        return load_plane<T, float>(op, dst, ids, region, nthreads, plane, convert);
    return load_plane<T, double>(op, dst, ids, region, nthreads, plane, convert);
}

// load_plane's row form of a per-pixel `convert(raw, inside)`.
template<class Convert>
auto each_pixel(Convert convert)
{
    return [convert](const auto* in, int nc, int n, bool inside, auto* out) {
        for (int i = 0; i < n; ++i)
            out[i] = convert(in + std::ptrdiff_t(i) * nc, inside);
    };
}

// The whole-number ids of `wide` (outside pixels as INT64_MIN) numbered
// densely in their order, zero at the first non-negative id: equality and
// sign are kept.
void renumber(const Plane<int64_t>& wide, IdPlane& plane)
{
    constexpr int64_t outside = std::numeric_limits<int64_t>::min();
    std::vector<int64_t> sorted(wide.values.begin(), wide.values.end());
    std::sort(sorted.begin(), sorted.end());
    sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
    sorted.erase(std::remove(sorted.begin(), sorted.end(), outside), sorted.end());
    const auto zero = std::lower_bound(sorted.begin(), sorted.end(), int64_t(0));
    plane.region = wide.region;
    plane.values.resize(wide.values.size());
    for (size_t i = 0; i < wide.values.size(); ++i) {
        const int64_t v = wide.values[i];
        plane.values[i] = v == outside ? no_guide_id
                                       : Id(std::lower_bound(sorted.begin(), sorted.end(), v)
                                            - zero);
    }
}

// The two kinds of id: object ids keep their sign, reflect ids take every
// negative value as -1 ("not specular"), before rounding.
enum class IdKind { object, reflect };

// An id rounded to the nearest whole number, clamped inside int64's range;
// NaN (and for reflect ids, any negative value) as -1.
template<IdKind kind, class Raw>
int64_t exact_id(Raw v)
{
    constexpr Raw limit = Raw(9.0e18);
    const bool none = std::isnan(v) || (kind == IdKind::reflect && v < Raw(0));
    return none ? int64_t(-1) : int64_t(std::nearbyint(std::clamp(v, -limit, limit)));
}

// The `n` ids of `in` (`nc` values apart) in 32 bits, into `out`: a loop the
// compiler vectorises, redone id by id when a NaN or an id beyond 32 bits
// shows. Returns true when some id does not fit (it is stored as 0).
template<IdKind kind, class Raw>
bool ids_in_32_bits(const Raw* in, int nc, int n, Id* out)
{
    constexpr Raw low = Raw(-2147483648.0), high = Raw(2147483648.0);
    int rare = 0;
    for (int i = 0; i < n; ++i) {
        const Raw v     = in[std::ptrdiff_t(i) * nc];
        const Raw id    = std::nearbyint(v);
        const bool fits = (id > low) & (id < high);  // false for NaN
        if constexpr (kind == IdKind::reflect) {
            const bool negative = v < Raw(0);
            rare |= !fits & !negative;
            out[i] = negative ? Id(-1) : Id(fits ? id : Raw(0));
        } else {
            rare |= !fits;
            out[i] = Id(fits ? id : Raw(0));
        }
    }
    if (!rare)
        return false;
    bool wide = false;
    for (int i = 0; i < n; ++i) {
        const int64_t id = exact_id<kind>(in[std::ptrdiff_t(i) * nc]);
        const bool fits  = id > no_guide_id && id <= std::numeric_limits<Id>::max();
        wide |= !fits;
        out[i] = Id(fits ? id : 0);
    }
    return wide;
}

// Ids of `kind`, no_guide_id outside the data window: stored as they are
// when every one fits in 32 bits, else renumbered from a 64-bit plane.
template<IdKind kind>
bool load_id_plane(const char* op, ImageBuf& dst, const ImageBuf& ids, const ROI& region,
                   int nthreads, IdPlane& plane)
{
    std::atomic<bool> wide_ids { false };
    const bool ok = load_raw_ids(
        op, dst, ids, region, nthreads, plane,
        [&](const auto* in, int nc, int n, bool inside, Id* out) {
            if (!inside)
                std::fill_n(out, n, no_guide_id);
            else if (ids_in_32_bits<kind>(in, nc, n, out))
                wide_ids.store(true, std::memory_order_relaxed);
        });
    if (!ok || !wide_ids)
        return ok;
    Plane<int64_t> wide;
    const auto wide_id = [](const auto* v, bool inside) {
        return inside ? exact_id<kind>(*v) : std::numeric_limits<int64_t>::min();
    };
    if (!load_raw_ids(op, dst, ids, region, nthreads, wide, each_pixel(wide_id)))
        return false;
    renumber(wide, plane);
    return true;
}

}  // namespace

bool load_object_ids(const char* op, ImageBuf& dst, const ImageBuf& ids, const ROI& region,
                     int nthreads, IdPlane& plane)
{
    return load_id_plane<IdKind::object>(op, dst, ids, region, nthreads, plane);
}

bool load_reflect_ids(const char* op, ImageBuf& dst, const ImageBuf& ids, const ROI& region,
                      int nthreads, IdPlane& plane)
{
    return load_id_plane<IdKind::reflect>(op, dst, ids, region, nthreads, plane);
}

bool load_normals(const char* op, ImageBuf& dst, const ImageBuf& normals, const ROI& region,
                  int nthreads, NormalPlanes& planes)
{
    planes.components = Planes<float>(region, 3);
    float* x = planes.components.values[0].data();
    float* y = planes.components.values[1].data();
    float* z = planes.components.values[2].data();
    return load_rows<float>(
        op, dst, normals, region, nthreads,
        [x, y, z](const float* in, int nc, int count, bool inside, size_t first) {
            for (int i = 0; i < count; ++i) {  // branch-free: the compiler vectorises it
                const float* v = in + std::ptrdiff_t(i) * nc;
                const double len = std::sqrt(double(v[0]) * v[0] + double(v[1]) * v[1]
                                             + double(v[2]) * v[2]);
                const bool usable
                    = inside & (len > 0.0) & (len <= std::numeric_limits<double>::max());
                const double scale = 1.0 / (usable ? len : 1.0);  // one division, not three
                x[first + i]       = usable ? float(v[0] * scale) : 0.0f;
                y[first + i]       = usable ? float(v[1] * scale) : 0.0f;
                z[first + i]       = usable ? float(v[2] * scale) : 0.0f;
            }
        });
}

bool load_depths(const char* op, ImageBuf& dst, const ImageBuf& depth, const ROI& region,
                 int nthreads, Plane<float>& plane)
{
    return load_plane<float, float>(op, dst, depth, region, nthreads, plane,
                                    each_pixel([](const float* d, bool inside) {
                                        const bool far = !inside || !std::isfinite(*d)
                                                         || *d >= infinitely_far;
                                        return far ? std::numeric_limits<float>::infinity()
                                                   : *d;
                                    }));
}

}  // namespace mcdenoise
