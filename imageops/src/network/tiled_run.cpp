// tiled_run.cpp: a network over a whole image, tile by tile (tiled_run.h).
#include "network/tiled_run.h"

#include "network/tiling.h"

#include <algorithm>
#include <new>
#include <vector>

namespace mcdenoise {

long long max_tile_pixels(UNet& net, uint64_t budget_bytes, std::string& error)
{
    // The working memory is affine in the pixels: measure it at two sizes.
    const int small = 256, large = 512;
    const size_t at_small = net.working_bytes(small, small, error);
    const size_t at_large = net.working_bytes(large, large, error);
    if (at_small == 0 || at_large == 0)
        return 0;
    const double pixels_small = double(small) * small, pixels_large = double(large) * large;
    const double slope  = double(at_large - at_small) / (pixels_large - pixels_small);
    const double fixed  = double(at_small) - slope * pixels_small;
    const double tensors = double(net.layout().input_channels + unet_output_channels) * sizeof(float);
    const double pixels = (double(budget_bytes) - std::max(fixed, 0.0)) / (slope + tensors);
    return std::max(1LL, static_cast<long long>(std::min(pixels, 1e15)));
}

int memory_limited_min_side(const UNet& net) { return 4 * net.layout().tile_overlap(); }

bool run_tiled(UNet& net, const NetworkImages& images, const NetworkInput& input,
               long long max_tile_pixels, int min_side, const RgbOut& output, int nthreads,
               const std::function<void(int done, int total)>& progress, std::string& error)
{
    TilePlan plan;
    if (!plan_tiles(output.width, output.height, net.layout().tile_overlap(), max_tile_pixels, plan,
                    error, min_side))
        return false;
    const int channels  = net.layout().input_channels;
    const size_t pixels = size_t(plan.tile_width) * size_t(plan.tile_height);
    std::vector<float> tensor_in, tensor_out;
    try {
        tensor_in.resize(pixels * size_t(channels));
        tensor_out.resize(pixels * unet_output_channels);
    } catch (const std::bad_alloc&) {
        error = "out of memory for a tile of " + std::to_string(plan.tile_width) + "x"
                + std::to_string(plan.tile_height) + " pixels";
        return false;
    }
    const int total = int(plan.tiles.size());
    for (int i = 0; i < total; ++i) {
        const Tile& tile = plan.tiles[size_t(i)];
        if (!write_input_tile(images, input, tile, channels, tensor_in.data())) {
            error = "the network's input does not fit its tile (an image of another size?)";
            return false;
        }
        if (!net.run(tensor_in.data(), plan.tile_height, plan.tile_width, tensor_out.data(), nthreads,
                     error))
            return false;
        if (!read_output_tile(tensor_out.data(), input, tile, output)) {
            error = "the network's output does not fit its tile";
            return false;
        }
        if (progress)
            progress(i + 1, total);
    }
    return true;
}

}  // namespace mcdenoise
