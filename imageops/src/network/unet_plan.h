// unet_plan.h: a UNet laid out on oneDNN for one image size: its primitives
// (convolution + ReLU, pooling, upsampling), the weights reordered once into
// the layout each convolution chose, and one arena holding every activation,
// implemented in unet_plan.cpp.
//
// Memory: a level's decoder input [upsampled, level input] is one buffer per
// level, written in place (channels are padded to the block size, so a
// block-aligned range of channels of an nChw<block>c tensor of one image is
// one contiguous run of floats); every convolution output lives in one of two
// scratch buffers shared by all levels, since only one level's are live at a
// time. A plan is made in two steps: `create` (primitives, sizes: what
// working_bytes needs) and `allocate` (the arena and the reordered weights).
#pragma once

#include "network/unet_layout.h"

#include <cstddef>
#include <memory>
#include <string>

namespace mcdenoise {

class UNetPlan {
public:
    ~UNetPlan();

    /// Plans `layout` for `height` x `width` (positive multiples of
    /// `unet_alignment`). Returns null with `error` set if oneDNN cannot.
    static std::unique_ptr<UNetPlan> create(const UNetLayout& layout, int height, int width,
                                            std::string& error);

    int height() const;
    int width() const;
    /// The bytes of the arena, the scratchpad and the reordered weights.
    size_t working_bytes() const;

    /// Allocates the arena and reorders the weights; false with `error`
    /// set when memory runs out or oneDNN fails. Done once, before `run`.
    bool allocate(std::string& error);
    /// Runs the network (see UNet::run); allocate() must have succeeded.
    bool run(const float* input, float* output, std::string& error);

private:
    struct Impl;
    explicit UNetPlan(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

/// The channel block of oneDNN's layout on this CPU: 16 with AVX-512, else 8.
int unet_channel_block();

}  // namespace mcdenoise
