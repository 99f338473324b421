// tiling.h: how an image is cut into the tiles the network runs on, as
// OIDN 2.x's UNetFilter does (core/unet_filter.cpp, init and execute): one
// tile of the image padded up to a multiple of 16 when it fits the budget;
// otherwise tiles of one aligned size overlapping by the network's
// receptive field, whose written parts abut and cover the image exactly;
// implemented in tiling.cpp.
#pragma once

#include <string>
#include <vector>

namespace mcdenoise {

/// The alignment of a tile's size and of its data inside the tile: the
/// network pools four times.
constexpr int tile_alignment = 16;
/// The smallest side OIDN cuts a tile down to, whatever the budget, when
/// four overlaps are less.
constexpr int tile_min_side = 768;

/// A rectangle of pixels in image coordinates.
struct TileRect {
    int x      = 0;
    int y      = 0;
    int width  = 0;
    int height = 0;
};

/// One tile: what the network's input tensor holds and what its output
/// gives back.
struct Tile {
    /// The image area the tile's tensor spans: tensor pixel (i, j) (column,
    /// row) is image pixel (tensor.x + i, tensor.y + j). Its size is the
    /// plan's tile size. It may reach past the right and bottom edges of
    /// the image, by less than 16 pixels.
    TileRect tensor;
    /// The pixels read into the tensor: inside the image and inside
    /// `tensor`. Every other tensor pixel is zero, also where `tensor`
    /// covers image pixels outside `input` (OIDN aligns a last, shorter
    /// tile's data to the bottom right of its tensor and pads it with zeros
    /// on both sides).
    TileRect input;
    /// The pixels the tile writes: inside `input`, which reaches `overlap`
    /// pixels beyond it on every side but at the image's edges. The outputs
    /// of a plan's tiles partition the image.
    TileRect output;
};

/// The tiles of an image.
struct TilePlan {
    /// The size of every tile's tensor: multiples of `tile_alignment`.
    int tile_width  = 0;
    int tile_height = 0;
    /// The tiles along each side.
    int columns = 0;
    int rows    = 0;
    /// The tiles, row by row, left to right: `rows * columns` of them.
    std::vector<Tile> tiles;
};

/// `size` rounded up to a multiple of `tile_alignment`.
int padded_size(int size);

/// The smallest tile side the plan cuts down to for `overlap`:
/// max(4 * overlap, `tile_min_side`), rounded up to `tile_alignment`.
int min_tile_side(int overlap);

/// Plans the tiles of a `width` x `height` image whose tiles overlap by
/// `overlap` pixels on each inner side (the network's receptive field over
/// 2, rounded up to 16: 96 for the base network, 112 for the large), with
/// at most `max_tile_pixels` pixels a tile. The whole image is one tile of
/// `padded_size` sides when that fits; otherwise, as OIDN does, the tile's
/// height is cut while it is taller than wide and above the minimum, else
/// its width, one more tile along that side at a time, until the tile
/// fits, no side going below `min_tile_side(overlap)`: the plan's tiles
/// exceed `max_tile_pixels` when tiles of that side do. Returns false, with
/// `error` saying why and `plan` unchanged, unless width and height are 1
/// to 2^30, overlap is a non-negative multiple of 16 below 2^24 and
/// max_tile_pixels is positive.
/// `min_side`, when positive, replaces `min_tile_side(overlap)` (rounded
/// up to `tile_alignment`, at least 2 * overlap + `tile_alignment`): a
/// memory limit may need tiles smaller than OIDN's, at the cost of more
/// overlap computed.
bool plan_tiles(int width, int height, int overlap, long long max_tile_pixels, TilePlan& plan,
                std::string& error, int min_side = 0);

}  // namespace mcdenoise
