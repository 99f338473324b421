// tiled_run.h: one network over a whole image, tile by tile as OIDN does
// (tiling.h's plan, tile_io.h's tensors), within a memory budget;
// implemented in tiled_run.cpp.
#pragma once

#include "network/tile_io.h"
#include "network/unet.h"

#include <cstdint>
#include <functional>
#include <string>

namespace mcdenoise {

/// OIDN's largest tile when no memory limit is set: 2160 x 2160 pixels.
constexpr long long default_max_tile_pixels = 2160LL * 2160LL;

/// The smallest tile side under a memory limit: four overlaps (448 pixels
/// for the large networks), where OIDN stops at 768 whatever its limit;
/// half of such a tile's pixels are overlap.
int memory_limited_min_side(const UNet& net);

/// The most pixels a tile of `net` may have for its run to take at most
/// `budget_bytes`: the network's activations, scratchpad and weights, and
/// the tile's input and output tensors. At least 1 (the plan then takes
/// its smallest tiles). 0 with `error` set when oneDNN cannot plan.
long long max_tile_pixels(UNet& net, uint64_t budget_bytes, std::string& error);

/// Runs `net` over `images` into `output` (of the same size; it must not
/// share memory with an input), tile by tile with at most
/// `max_tile_pixels` a tile, `input` saying how the tensors are encoded.
/// `min_side` as plan_tiles takes it (0: OIDN's). `progress` (may be
/// empty) is called after each tile with the tiles done and their count.
/// False with `error` set when a tile cannot be written or the network
/// fails.
bool run_tiled(UNet& net, const NetworkImages& images, const NetworkInput& input,
               long long max_tile_pixels, int min_side, const RgbOut& output, int nthreads,
               const std::function<void(int done, int total)>& progress, std::string& error);

}  // namespace mcdenoise
