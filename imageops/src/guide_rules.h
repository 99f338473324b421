// guide_rules.h: the viability rules of the guided filters (SPEC.md), each
// with the map of windows it makes wholly viable (the fast path).
#pragma once

#include "guides.h"
#include "window.h"


#include <cstdint>
#include <vector>

namespace mcdenoise {

/// Which ROI pixels' windows are wholly viable.
struct UniformMap {
    OIIO::ROI roi;
    std::vector<uint8_t> flags;

    bool at(int x, int y) const
    {
        return flags[size_t(y - roi.ybegin) * roi.width() + size_t(x - roi.xbegin)];
    }
};

/// Where keys change: 1 at each pixel of `region` with a 4-neighbour (in
/// `region`) of another key, keys compared by `same(i, j)` on flat
/// row-major indices of `region`.
struct KeyEdges {
    OIIO::ROI region;
    std::vector<uint8_t> flags;
};

template<class Same>
KeyEdges key_edges(const OIIO::ROI& region, int nthreads, Same&& same);

/// Conservatively, the windows of radius `r` around the pixels of `roi` that
/// are one key: those holding no pixel next to a key change (a window with
/// two keys always holds such a pair; a window touched from outside is
/// wrongly left out, which only sends it down the slow path). `edges` must
/// cover the region the windows reach.
UniformMap uniform_map(const KeyEdges& edges, const OIIO::ROI& roi, int r, int nthreads);

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

    bool uniform(int x, int y) const { return uniform_windows.at(x, y); }
    void row_weights(int px, int py, int qy, Span xs, float* w) const
    {
        matching_keys(ids.from(xs.begin, qy), ids.at(px, py), xs, w);
    }
};

/// Where object ids change, over the ids' region.
KeyEdges id_edges(const IdPlane& ids, int nthreads);

/// The object rule over `ids` for windows of side `size` around `roi`.
SameObject same_object_rule(const IdPlane& ids, const OIIO::ROI& roi, int size,
                            int nthreads);

template<class Same>
KeyEdges key_edges(const OIIO::ROI& region, int nthreads, Same&& same)
{
    KeyEdges edges { region, std::vector<uint8_t>(region.npixels()) };
    uint8_t* flags = edges.flags.data();
    parallel_rows(region, nthreads, [&, flags](int ay) {
        // Local copies: byte stores could otherwise alias the bounds.
        const int w = region.width(), h = region.height(), y = ay - region.ybegin;
        uint8_t* out = flags + size_t(y) * w;
        const size_t row = size_t(y) * w;
        for (int x = 0; x < w; ++x) {
            const size_t i = row + x;
            out[x] = (x > 0 && !same(i, i - 1)) || (x < w - 1 && !same(i, i + 1))
                     || (y > 0 && !same(i, i - w)) || (y < h - 1 && !same(i, i + w));
        }
    });
    return edges;
}

}  // namespace mcdenoise
