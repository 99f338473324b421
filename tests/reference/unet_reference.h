// unet_reference.h: an independent, deliberately plain implementation of
// OIDN 2.x's UNets for the tests: double precision, planar tensors, every
// multiply of every 3x3 convolution written out, and the networks spelt
// layer by layer as OIDN's training/model.py defines them (the default and
// small ones from enc_conv0, the large one from enc_conv1a). No code shared
// with the engine (network/unet*.h) beyond the weights' reader.
#pragma once

#include "network/tza.h"

#include <vector>

namespace unetref {

/// Planar activations: `channels` planes of `height` x `width`.
struct Activations {
    int channels = 0, height = 0, width = 0;
    std::vector<double> values;

    double& at(int c, int y, int x) { return values[(size_t(c) * height + y) * width + x]; }
    double at(int c, int y, int x) const { return values[(size_t(c) * height + y) * width + x]; }
};

/// A 3x3 convolution named `name` of `weights` (padding 1 with zeros,
/// stride 1, bias), then ReLU.
Activations conv_relu(const mcdenoise::TensorMap& weights, const char* name, const Activations& x);
/// 2x2 max pooling, stride 2.
Activations pool(const Activations& x);
/// 2x nearest upsampling.
Activations upsample(const Activations& x);
/// The channels of `a` then those of `b`.
Activations concat(const Activations& a, const Activations& b);

/// The whole UNet of `weights` (default, small or large, told apart by the
/// names of its tensors) on `input`.
Activations unet(const mcdenoise::TensorMap& weights, const Activations& input);

}  // namespace unetref
