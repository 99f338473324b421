// tiling.cpp: the tile plan (tiling.h): each side's tile size and count
// found as OIDN's UNetFilter::init finds them, then each tile's rectangles
// laid out per side as its execute does.
#include "network/tiling.h"

#include <algorithm>
#include <utility>

namespace mcdenoise {

namespace {

/// The largest image side and overlap a plan takes.
constexpr int max_side    = 1 << 30;
constexpr int max_overlap = 1 << 24;

/// One side of the plan: the image's, the tile's, and how many tiles.
struct Side {
    long long size;
    long long tile;
    long long count;
    long long min_tile;
};

long long ceil_div(long long a, long long b) { return (a + b - 1) / b; }

long long padded(long long size) { return ceil_div(size, tile_alignment) * tile_alignment; }

/// Shrinks the tile of `side` so that one more tile goes along it (OIDN's
/// step: the side plus the overlaps shared evenly, aligned, kept between
/// the minimum and one alignment below the current tile), and recounts the
/// tiles it takes.
void cut(Side& side, int overlap)
{
    const long long overlaps = 2LL * overlap;
    const long long wanted   = ceil_div(side.size + overlaps * side.count, side.count + 1);
    side.tile  = std::clamp(padded(wanted), side.min_tile, side.tile - tile_alignment);
    side.count = std::max(ceil_div(side.size - overlaps, side.tile - overlaps), 1LL);
}

/// Where tile `i` of `side` lies along it, as the x (or y) and width (or
/// height) of its three rectangles.
struct Span {
    int tensor;
    int input;
    int input_size;
    int output;
    int output_size;
};

Span span(const Side& side, int i, int overlap)
{
    const long long input       = i * (side.tile - 2LL * overlap);
    const long long before      = i > 0 ? overlap : 0;
    const long long after       = i < side.count - 1 ? overlap : 0;
    const long long input_size  = std::min(side.size - input, side.tile);
    const long long align_start = side.tile - padded(input_size);
    return { int(input - align_start), int(input), int(input_size), int(input + before),
             int(input_size - before - after) };
}

}  // namespace

int padded_size(int size) { return int(padded(size)); }

int min_tile_side(int overlap) { return int(padded(std::max(4LL * overlap, 1LL * tile_min_side))); }

bool plan_tiles(int width, int height, int overlap, long long max_tile_pixels, TilePlan& plan,
                std::string& error, int min_side)
{
    if (width < 1 || width > max_side || height < 1 || height > max_side) {
        error = "image size " + std::to_string(width) + "x" + std::to_string(height)
                + " (each side must be 1 to 2^30)";
        return false;
    }
    if (overlap < 0 || overlap >= max_overlap || overlap % tile_alignment != 0) {
        error = "tile overlap " + std::to_string(overlap)
                + " (must be a non-negative multiple of 16 below 2^24)";
        return false;
    }
    if (max_tile_pixels < 1) {
        error =
            "maximum tile size " + std::to_string(max_tile_pixels) + " pixels (must be positive)";
        return false;
    }
    const long long min_tile = min_side > 0
                                   ? std::max(padded(min_side), 2LL * overlap + tile_alignment)
                                   : min_tile_side(overlap);
    Side w { width, padded(width), 1, min_tile };
    Side h { height, padded(height), 1, min_tile };
    while (h.tile * w.tile > max_tile_pixels) {
        if (h.tile > h.min_tile && h.tile > w.tile)
            cut(h, overlap);
        else if (w.tile > w.min_tile)
            cut(w, overlap);
        else
            break;
    }
    TilePlan out;
    out.tile_width  = int(w.tile);
    out.tile_height = int(h.tile);
    out.columns     = int(w.count);
    out.rows        = int(h.count);
    for (int i = 0; i < out.rows; ++i) {
        const Span y = span(h, i, overlap);
        for (int j = 0; j < out.columns; ++j) {
            const Span x = span(w, j, overlap);
            out.tiles.push_back({ { x.tensor, y.tensor, out.tile_width, out.tile_height },
                                  { x.input, y.input, x.input_size, y.input_size },
                                  { x.output, y.output, x.output_size, y.output_size } });
        }
    }
    plan = std::move(out);
    return true;
}

}  // namespace mcdenoise
