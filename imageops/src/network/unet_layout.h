// unet_layout.h: the shape of one of OIDN 2.x's UNets, read from the names
// and shapes of its weights (enc_conv*, dec_conv*): which 3x3 convolutions
// run at which resolution level, what each decoder level concatenates, and
// the figures that follow from the shape (FLOPs per pixel, receptive field,
// tile overlap); implemented in unet_layout.cpp. Pure bookkeeping: the
// engine that runs it is unet.h.
#pragma once

#include "network/tza.h"

#include <string>
#include <vector>

namespace mcdenoise {

/// The resolution levels of every OIDN UNet: full, 1/2, 1/4, 1/8, 1/16.
constexpr int unet_levels = 5;
/// Image and tile sides must be multiples of this (2^(levels-1)).
constexpr int unet_alignment = 1 << (unet_levels - 1);
/// The channels of every network's output (colour, albedo or normal).
constexpr int unet_output_channels = 3;

/// One 3x3 convolution (padding 1, stride 1, bias, ReLU after it).
struct UNetConv {
    /// The weights' name without ".weight", e.g. "enc_conv5a".
    std::string name;
    /// Input and output channels, as in the weights.
    int in_channels = 0;
    int out_channels = 0;
    /// The weights (out x in x 3 x 3, row-major) and the bias (out).
    const std::vector<float>* weight = nullptr;
    const std::vector<float>* bias = nullptr;
};

/// The convolutions of one resolution level, in the order they run.
struct UNetLevel {
    /// Run on the level's input: the network input at level 0, else the
    /// 2x2 max pooling of the previous level's encoder output.
    std::vector<UNetConv> encoder;
    /// Run, on every level but the last, on the concatenation [2x nearest
    /// upsampling of the level below's decoder output (of its encoder
    /// output, for the level above the last), this level's input]. Empty
    /// on the last level.
    std::vector<UNetConv> decoder;
};

/// A UNet's shape. The pointers in its convolutions point into the
/// TensorMap it was read from, which must outlive it.
struct UNetLayout {
    /// The channels of the network input: 3 (colour, or the albedo or
    /// normal alone), 6 (+ albedo) or 9 (+ albedo + normal).
    int input_channels = 0;
    std::vector<UNetLevel> levels;

    /// The channels of level `level`'s input (the skip its decoder
    /// concatenates): `input_channels` at level 0.
    int level_input_channels(int level) const;
    /// The channels the decoder of `level` upsamples from the level below.
    int upsampled_channels(int level) const;
    /// Floating-point operations per full-resolution pixel (a multiply-add
    /// counts 2): every convolution's 2 x 9 x in x out, over 4^level.
    double flops_per_pixel() const;
    /// The side of the square of input pixels one output pixel depends on.
    int receptive_field() const;
    /// The overlap on each side of a tile for tiled output to equal the
    /// whole image's: half the receptive field rounded up to the alignment.
    int tile_overlap() const;
    /// Every convolution, in the order they run.
    std::vector<const UNetConv*> convolutions() const;
};

/// Reads the UNet of `tensors` (a .tza file's; `source` names it in the
/// error) into `layout`. Returns false with `error` naming `source` and the
/// tensor when a tensor is not of an OIDN UNet (an unknown name, a weight
/// without its bias, a shape that is not 3x3, channels that do not chain
/// from one convolution to the next and through each concatenation, a
/// level without convolutions, an output other than 3 channels).
bool read_unet_layout(const TensorMap& tensors, const std::string& source, UNetLayout& layout,
                      std::string& error);

}  // namespace mcdenoise
