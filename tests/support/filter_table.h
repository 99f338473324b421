// filter_table.h: every library filter as one row (its name, the guides it
// reads, and one call with the common parameters), for the tests and fuzz
// targets that run them all: determinism across threads and ROI splits,
// hostile input. A new filter is one more row in filter_table.cpp.
#pragma once

#include <OpenImageIO/imagebuf.h>

#include <ostream>
#include <vector>

namespace testfilters {

using OIIO::ImageBuf;
using OIIO::ROI;

/// The guide images a filter may read, by role (the library's argument order).
struct GuideSet {
    ImageBuf object_id, reflect_id, normal, depth, albedo, variance;
};

/// Which guides a row reads (bit flags), so callers build only those.
enum GuideBit : unsigned {
    needs_id = 1u << 0,
    needs_reflect_id = 1u << 1,
    needs_normal = 1u << 2,
    needs_depth = 1u << 3,
    needs_albedo = 1u << 4,
    needs_variance = 1u << 5,
};

/// A filter's bool form with the shared parameters (the others at the
/// header's named defaults): `size` is the window
/// side; for `dof` the level count (focus at the middle level, so its
/// widest window is `size` too); for `atrous` twice the iteration count,
/// for `nlmeans` and `clamp_fireflies` twice the (search) radius; unused by
/// `demodulate`, `remodulate` and `denoise`.
using RunFilter = bool (*)(ImageBuf& dst, const ImageBuf& beauty, const GuideSet& guides, int size, ROI roi,
                           int nthreads);

/// One filter.
struct FilterRow {
    const char* name;
    unsigned guides;  ///< GuideBit flags
    RunFilter run;
    /// True for the per-pixel operations that copy non-finite values (and
    /// may overflow huge ones) instead of leaving them out of a window.
    bool per_pixel = false;
};

/// GoogleTest prints a row by its name (so CTest names stay short).
inline void PrintTo(const FilterRow& row, std::ostream* os) { *os << row.name; }

/// Every filter of the library, in header order.
const std::vector<FilterRow>& filter_table();

/// The rows of `filter_table()` for which `keep(row)` is true, for a check
/// that applies to some filters only (instantiated for those alone, never
/// skipped).
std::vector<FilterRow> filter_rows(bool (*keep)(const FilterRow&));

/// The channel count the library expects for each guide role.
int guide_channels(GuideBit guide);

}  // namespace testfilters
