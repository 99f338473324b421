// guide_rules.h: the viability rules of the guided filters (docs/filters.md), each
// with the map of windows it makes wholly viable (the fast path), found
// exactly from where the keys (ids) change between neighbouring pixels.
#pragma once

#include "core/guides.h"
#include "core/window.h"


#include <cstdint>
#include <vector>

namespace mcdenoise {

/// Up to four keys (object id; object and reflect id; ...) tracked at once,
/// key k in bit k.
using KeyBits = uint8_t;

/// Per ROI pixel (the plane's region), the keys that change somewhere in
/// its window.
struct UniformMap : Plane<KeyBits> {
    using Plane<KeyBits>::Plane;

    /// For the pixels of row `y` along `xs`: 1 where the window holds one
    /// value of every key in `keys`, into `out`.
    void uniform_row(int y, Span xs, KeyBits keys, uint8_t* out) const
    {
        const KeyBits* c = from(xs.begin, y);
        for (int i = 0; i < xs.size(); ++i)
            out[i] = !(c[i] & keys);
    }
};

/// Where keys change over `region`: per pixel, bit k set when key k differs
/// from the right neighbour's, bit 4 + k when it differs from the one below
/// (pairs leaving `region` never change).
using KeyChanges = Plane<uint8_t>;

/// The key changes of `region`; `differ(i, j)` gives the keys that differ
/// between flat row-major indices i and j of `region`.
template<class Differ>
KeyChanges key_changes(const OIIO::ROI& region, int nthreads, Differ&& differ);

/// Exactly, per pixel of `roi`, the keys that change between two
/// neighbouring pixels of its window of radius `r` (clipped to the changes'
/// region, which must cover every window).
UniformMap uniform_map(const KeyChanges& changes, const OIIO::ROI& roi, int r, int nthreads);

/// Read a guide's object ids over what a window of side `size` reaches from
/// `roi` and one pixel more, after checking the guide.
bool load_window_ids(const char* op, OIIO::ImageBuf& dst, const OIIO::ImageBuf& beauty,
                     const OIIO::ImageBuf& object_id, const OIIO::ROI& roi, int size,
                     int nthreads, IdPlane& ids);

/// 1 where `keys` along `xs` equal `key`, else 0, into `w`.
template<class Key>
void matching_keys(const Key* keys, Key key, Span xs, float* w)
{
    for (int i = 0; i < xs.size(); ++i)
        w[i] = keys[i] == key ? 1.0f : 0.0f;
}

/// Object rule: q is viable iff id(q) == id(p).
struct SameObject {
    const IdPlane& ids;
    UniformMap uniform_windows;

    /// The weights depend on the center's id alone.
    Id key(int x, int y) const { return ids.at(x, y); }

    void uniform_row(int y, Span xs, uint8_t* out) const
    {
        uniform_windows.uniform_row(y, xs, 1, out);
    }
    void row_weights(int px, int py, int qy, Span xs, float* w) const
    {
        matching_keys(ids.from(xs.begin, qy), ids.at(px, py), xs, w);
    }
    void offset_weights(int y, Span xs, int dx, int qy, float* w) const
    {
        const Id* center = ids.from(xs.begin, y);
        const Id* id     = ids.from(xs.begin + dx, qy);
        for (int i = 0; i < xs.size(); ++i)
            w[i] = id[i] == center[i] ? 1.0f : 0.0f;
    }
};

/// Where object ids change, over the ids' region (key 0).
KeyChanges id_changes(const IdPlane& ids, int nthreads);

/// The object rule over `ids` (whose changes are `changes`) for windows of
/// side `size` around `roi`.
SameObject same_object_rule(const IdPlane& ids, const KeyChanges& changes,
                            const OIIO::ROI& roi, int size, int nthreads);

template<class Differ>
KeyChanges key_changes(const OIIO::ROI& region, int nthreads, Differ&& differ)
{
    KeyChanges changes(region);
    uint8_t* flags = changes.values.data();
    parallel_rows(region, nthreads, [&region, flags, differ](int ay) {
        // Local copies (of `differ` too): byte stores could otherwise alias
        // the bounds and the planes `differ` reads.
        const auto local_differ = differ;
        const int w = region.width(), h = region.height(), y = ay - region.ybegin;
        uint8_t* out    = flags + size_t(y) * w;
        const size_t row = size_t(y) * w;
        // Branch-free loops the compiler vectorises; the last column has
        // no right neighbour, the last row none below.
        for (int x = 0; x < w - 1; ++x)
            out[x] = local_differ(row + x, row + x + 1);
        out[w - 1] = 0;
        if (y < h - 1)
            for (int x = 0; x < w; ++x)
                out[x] = uint8_t(out[x] | (local_differ(row + x, row + x + w) << 4));
    });
    return changes;
}

}  // namespace mcdenoise
