// tile_io.cpp: a tile's pixels into the input tensor and the output tensor
// back into pixels (tile_io.h). Both go a plane row at a time: the row's
// values gathered from the interleaved pixels and sanitised, the transfer
// applied to the contiguous row, zeros written around.
#include "network/tile_io.h"

#include "network/transfer.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <vector>

namespace mcdenoise {

namespace {

/// The channels of each of the input's images.
constexpr int rgb = 3;

/// `v` with NaN taken as 0, clamped to [lo, hi].
inline float clamped(float v, float lo, float hi)
{
    return std::isnan(v) ? 0.f : std::min(std::max(v, lo), hi);
}

/// How one image's values are sanitised on the way in: times `scale`, NaN
/// to 0, clamped to [lo, hi], then times `mul` plus `add`.
struct Sanitizer {
    float scale;
    float lo;
    float hi;
    float mul;
    float add;
};

/// A normal's sanitising: [-1, 1] mapped to [0, 1].
constexpr Sanitizer normal_sanitizer { 1.f, -1.f, 1.f, 0.5f, 0.5f };
/// An albedo's sanitising: [0, 1] as it is.
constexpr Sanitizer albedo_sanitizer { 1.f, 0.f, 1.f, 1.f, 0.f };

Sanitizer main_sanitizer(const NetworkInput& input)
{
    if (input.encoding == Encoding::normal)
        return { input.input_scale, -1.f, 1.f, 0.5f, 0.5f };
    return { input.input_scale, 0.f, input.encoding == Encoding::hdr ? FLT_MAX : 1.f, 1.f, 0.f };
}

/// Whether `r` is not empty and lies inside `outer`.
bool inside(const TileRect& r, const TileRect& outer)
{
    return r.width > 0 && r.height > 0 && r.x >= outer.x && r.y >= outer.y
           && r.x + r.width <= outer.x + outer.width && r.y + r.height <= outer.y + outer.height;
}

/// The rectangle of a `width` x `height` image.
TileRect image_rect(int width, int height) { return { 0, 0, width, height }; }

/// Whether `image` is given, valid and `width` x `height`.
bool matches(const RgbIn& image, int width, int height)
{
    return image.valid() && image.width == width && image.height == height;
}

/// Writes channel `c` of `count` pixels of `image` from (x, y) on to `out`,
/// sanitised by `s`.
void gather(const RgbIn& image, int c, const Sanitizer& s, int x, int y, int count, float* out)
{
    const float* p = image.pixel(x, y) + c;
    for (int i = 0; i < count; ++i, p += image.pixel_stride)
        out[i] = clamped(*p * s.scale, s.lo, s.hi) * s.mul + s.add;
}

/// Applies the main input's transfer for `encoding` to `count` values.
void encode(Encoding encoding, float* values, size_t count)
{
    if (encoding == Encoding::hdr)
        pu_encode_row(values, count);
    else if (encoding == Encoding::ldr)
        srgb_forward_row(values, count);
}

/// Inverts the main input's transfer for `encoding` on `count` values.
void decode(Encoding encoding, float* values, size_t count)
{
    if (encoding == Encoding::hdr)
        pu_decode_row(values, count);
    else if (encoding == Encoding::ldr)
        srgb_inverse_row(values, count);
}

/// Writes row `ty` of plane `c` of the input tensor of `tile` to `row`.
void write_plane_row(const NetworkImages& images, const NetworkInput& input, const Tile& tile,
                     int c, int ty, float* row)
{
    const TileRect& in = tile.input;
    const int y        = tile.tensor.y + ty;
    float* const end   = row + tile.tensor.width;
    if (c >= input_channels(input) || y < in.y || y >= in.y + in.height) {
        std::fill(row, end, 0.f);
        return;
    }
    float* const data = row + (in.x - tile.tensor.x);
    std::fill(row, data, 0.f);
    const int group = c / rgb;
    if (group == 0) {
        gather(images.main, c, main_sanitizer(input), in.x, y, in.width, data);
        encode(input.encoding, data, size_t(in.width));
    } else if (group == 1) {
        gather(images.albedo, c - rgb, albedo_sanitizer, in.x, y, in.width, data);
    } else {
        gather(images.normal, c - 2 * rgb, normal_sanitizer, in.x, y, in.width, data);
    }
    std::fill(data + in.width, end, 0.f);
}

/// Finishes `value`, decoded, as OIDN's output does for `input`: a normal
/// mapped back to [-1, 1], anything but HDR at most 1, then times
/// `output_scale`; 0 when that is 0 (OIDN's product would be NaN for an
/// infinite HDR value).
inline float finished(float value, const NetworkInput& input, float output_scale)
{
    if (input.encoding == Encoding::normal)
        value = std::max(value * 2.f - 1.f, -1.f);
    if (input.encoding != Encoding::hdr)
        value = std::min(value, 1.f);
    return output_scale != 0.f ? value * output_scale : 0.f;
}

}  // namespace

int input_channels(const NetworkInput& input)
{
    return rgb * (1 + int(input.albedo) + int(input.normal));
}

bool write_input_tile(const NetworkImages& images, const NetworkInput& input, const Tile& tile,
                      int channels, float* tensor)
{
    const int width  = images.main.width;
    const int height = images.main.height;
    if (tensor == nullptr || !matches(images.main, width, height)
        || (input.albedo && !matches(images.albedo, width, height))
        || (input.normal && (!input.albedo || !matches(images.normal, width, height)))
        || channels < input_channels(input) || !inside(tile.input, image_rect(width, height))
        || !inside(tile.input, tile.tensor))
        return false;
    const size_t plane = size_t(tile.tensor.width) * size_t(tile.tensor.height);
    for (int c = 0; c < channels; ++c)
        for (int ty = 0; ty < tile.tensor.height; ++ty)
            write_plane_row(images, input, tile, c, ty,
                            tensor + size_t(c) * plane + size_t(ty) * size_t(tile.tensor.width));
    return true;
}

bool read_output_tile(const float* tensor, const NetworkInput& input, const Tile& tile,
                      const RgbOut& output)
{
    const TileRect& out = tile.output;
    if (tensor == nullptr || !output.valid()
        || !inside(out, image_rect(output.width, output.height)) || !inside(out, tile.tensor))
        return false;
    const float output_scale = input.input_scale != 0.f ? 1.f / input.input_scale : 0.f;
    const size_t plane       = size_t(tile.tensor.width) * size_t(tile.tensor.height);
    std::vector<float> values(size_t(out.width));
    for (int y = out.y; y < out.y + out.height; ++y) {
        const size_t row =
            size_t(y - tile.tensor.y) * size_t(tile.tensor.width) + size_t(out.x - tile.tensor.x);
        for (int c = 0; c < rgb; ++c) {
            const float* src = tensor + size_t(c) * plane + row;
            for (int i = 0; i < out.width; ++i)
                values[size_t(i)] = clamped(src[i], 0.f, FLT_MAX);
            decode(input.encoding, values.data(), values.size());
            float* dst = output.pixel(out.x, y) + c;
            for (int i = 0; i < out.width; ++i, dst += output.pixel_stride)
                *dst = finished(values[size_t(i)], input, output_scale);
        }
    }
    return true;
}

}  // namespace mcdenoise
