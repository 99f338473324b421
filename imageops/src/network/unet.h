// unet.h: one of OIDN 2.x's UNets, loaded from its .tza weights and run in
// float32 on oneDNN (Debian's libdnnl 2.6): 3x3 convolutions with their
// ReLU fused, 2x2 max pooling and 2x nearest upsampling, every activation
// kept in oneDNN's blocked layout (nChw16c on AVX-512, nChw8c otherwise)
// from the first layer to the last, and every decoder concatenation
// written in place: the pooling and the upsampling write straight into
// the two halves of one buffer. Implemented in unet.cpp, on the per-size
// plan of unet_plan.h.
#pragma once

#include "network/unet_layout.h"

#include <cstddef>
#include <memory>
#include <string>

namespace mcdenoise {

class UNetPlan;

/// A loaded network, ready to run on images whose sides are multiples of
/// `unet_alignment`. Not safe to run from two threads at once (it keeps
/// the plan of the last size it ran); load one per thread instead.
class UNet {
public:
    UNet();
    ~UNet();
    UNet(UNet&&) noexcept;
    UNet& operator=(UNet&&) noexcept;

    /// Loads the weights file at `path`. Returns false with `error` naming
    /// the file (and the tensor) when it cannot be read, is not a .tza file
    /// or does not hold one of OIDN's UNets.
    bool load(const std::string& path, std::string& error);
    /// Loads already-read `tensors` (shared: several networks may run the
    /// same weights); `source` names them in errors.
    bool load(std::shared_ptr<const TensorMap> tensors, const std::string& source,
              std::string& error);
    /// True once a load succeeded.
    bool loaded() const;

    /// The network's shape; valid once loaded.
    const UNetLayout& layout() const;
    /// The file (or source) it was loaded from.
    const std::string& source() const;

    /// The bytes a run on a `height` x `width` image takes beyond its input
    /// and output: the activations, oneDNN's scratchpad and the weights in
    /// oneDNN's layout. Returns 0 (with `error` set) if oneDNN cannot plan
    /// that size.
    size_t working_bytes(int height, int width, std::string& error);

    /// Runs the network on `input`: `layout().input_channels` planes of
    /// `height` x `width` floats, each row-major; writes the 3 planes of
    /// its output to `output`. Both sides must be positive multiples of
    /// `unet_alignment`. `nthreads` threads (0: every hardware thread).
    /// Returns false with `error` set when oneDNN fails or memory runs out.
    bool run(const float* input, int height, int width, float* output, int nthreads,
             std::string& error);

    /// Frees the plan of the last size run (its activations, scratchpad
    /// and reordered weights); the next run makes it again.
    void release_plan();

private:
    /// The plan of `height` x `width`, made or reused.
    UNetPlan* plan_for(int height, int width, std::string& error);

    std::shared_ptr<const TensorMap> tensors_;
    UNetLayout layout_;
    std::string source_;
    std::unique_ptr<UNetPlan> plan_;
};

}  // namespace mcdenoise
