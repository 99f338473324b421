// tile_io.h: the pixels of one tile into the network's input tensor and the
// network's output tensor back into pixels, as OIDN 2.x's RT filter does
// (devices/cpu/cpu_input_process.isph, cpu_output_process.isph, the
// transfer function core/rt_filter.cpp picks): the main input scaled,
// sanitised and encoded, the auxiliary albedo and normal sanitised, zeros
// around; the output sanitised, decoded and scaled back. Tensors are
// planar float32, channel by channel, each a tile's rows (CHW);
// implemented in tile_io.cpp.
#pragma once

#include "network/rgb_pixels.h"
#include "network/tiling.h"

namespace mcdenoise {

/// What the network's main input (its first three channels) is, and so
/// how it is encoded.
enum class Encoding {
    /// Linear HDR colour: scaled, clamped to [0, FLT_MAX], `pu_encode`d.
    hdr,
    /// Linear LDR colour, or the albedo of the albedo prefilter: scaled,
    /// clamped to [0, 1], `srgb_forward`ed.
    ldr,
    /// Colour (or the prefilter's albedo) already sRGB-encoded: scaled,
    /// clamped to [0, 1], taken as it is.
    srgb,
    /// The normal of the normal prefilter: scaled, clamped to [-1, 1],
    /// mapped to [0, 1] by x 0.5 + 0.5.
    normal,
};

/// The network's input: its main input, then, when present, the auxiliary
/// albedo (3 channels) and normal (3 channels), in that order.
struct NetworkInput {
    Encoding encoding = Encoding::hdr;
    /// The main input is multiplied by this before it is sanitised (the
    /// autoexposure for HDR, 1 or the user's scale otherwise); the output is
    /// divided by it (multiplied by 0 when it is 0).
    float input_scale = 1.f;
    /// Whether the auxiliary albedo follows the main input: sanitised to
    /// [0, 1].
    bool albedo = false;
    /// Whether the auxiliary normal follows the albedo: sanitised to
    /// [-1, 1], then x 0.5 + 0.5. OIDN's networks take a normal only with
    /// an albedo.
    bool normal = false;
};

/// The images a tile is read from: `main` always; `albedo` and `normal`
/// when the input has them, of the main image's size.
struct NetworkImages {
    RgbIn main;
    RgbIn albedo;
    RgbIn normal;
};

/// The channels the network reads for `input`: 3, 6 or 9.
int input_channels(const NetworkInput& input);

/// Writes the input tensor of `tile` (of `tile.tensor`'s size, `channels`
/// planes) to `tensor`: for each pixel of `tile.input`, the main input
/// encoded as `input.encoding` says in planes 0-2, the albedo in 3-5 and
/// the normal in 6-8 when present; every other value 0 (the tensor's pixels
/// outside `tile.input`, and the planes from `input_channels(input)` to
/// `channels`, so that a network padded to more input channels can take
/// it). NaN is taken as 0 before clamping. Returns false, writing nothing,
/// when an image is missing, not `valid()` or of another size than the
/// main, a normal is asked for without an albedo, `channels` is fewer than
/// `input_channels(input)`, or `tile.input` is empty or not inside both
/// the image and `tile.tensor`.
bool write_input_tile(const NetworkImages& images, const NetworkInput& input, const Tile& tile,
                      int channels, float* tensor);

/// Writes the network's output for `tile.output` into `output`, reading
/// the first three planes of `tensor` (of `tile.tensor`'s size, planar
/// RGB): each value NaN to 0, clamped to [0, FLT_MAX], decoded (`hdr`:
/// `pu_decode`; `ldr`: `srgb_inverse`; `srgb`: as it is; `normal`: x 2 - 1,
/// then at least -1), at most 1 unless `hdr`, then divided by
/// `input.input_scale` as `NetworkInput` says (0 when the scale is 0, also
/// for an infinite value). HDR values are not clamped above: an output
/// beyond the curve's range decodes to +inf. Only the first three values
/// of each output pixel are written. Returns false, writing nothing, when
/// `output` is not `valid()`, or `tile.output` is empty or not inside both
/// `output` and `tile.tensor`.
bool read_output_tile(const float* tensor, const NetworkInput& input, const Tile& tile,
                      const RgbOut& output);

}  // namespace mcdenoise
