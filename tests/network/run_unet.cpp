// run_unet.cpp: runs one of OIDN's UNets on our engine for the check against
// independent implementations (tests/network/check_unet.py).
// Usage: run_unet WEIGHTS.tza INPUT.bin OUTPUT.bin [NTHREADS]
// A .bin tensor is int32 height, width, channels (little-endian), then
// height x width x channels float32 values, channel fastest (HWC). The input
// is the network's input as it is (no transfer function is applied); the
// output is its last layer's.
#include "network/unet.h"

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace {

struct HwcTensor {
    int32_t height = 0, width = 0, channels = 0;
    std::vector<float> values;
};

bool read_tensor(const std::string& path, HwcTensor& tensor, std::string& error)
{
    std::ifstream in(path, std::ios::binary);
    int32_t dims[3];
    if (!in.read(reinterpret_cast<char*>(dims), sizeof(dims)) || dims[0] <= 0 || dims[1] <= 0
        || dims[2] <= 0) {
        error = path + ": not a tensor file (int32 height, width, channels, then float32 values)";
        return false;
    }
    tensor.height   = dims[0];
    tensor.width    = dims[1];
    tensor.channels = dims[2];
    tensor.values.resize(size_t(dims[0]) * size_t(dims[1]) * size_t(dims[2]));
    if (!in.read(reinterpret_cast<char*>(tensor.values.data()),
                 std::streamsize(tensor.values.size() * sizeof(float)))) {
        error = path + ": truncated: fewer values than its dimensions say";
        return false;
    }
    return true;
}

bool write_tensor(const std::string& path, const HwcTensor& tensor)
{
    std::ofstream out(path, std::ios::binary);
    const int32_t dims[3] = { tensor.height, tensor.width, tensor.channels };
    out.write(reinterpret_cast<const char*>(dims), sizeof(dims));
    out.write(reinterpret_cast<const char*>(tensor.values.data()),
              std::streamsize(tensor.values.size() * sizeof(float)));
    return bool(out);
}

/// HWC values to C planes of H x W, or back.
std::vector<float> transpose(const std::vector<float>& values, size_t pixels, size_t channels,
                             bool to_planes)
{
    std::vector<float> out(values.size());
    for (size_t p = 0; p < pixels; ++p)
        for (size_t c = 0; c < channels; ++c) {
            if (to_planes)
                out[c * pixels + p] = values[p * channels + c];
            else
                out[p * channels + c] = values[c * pixels + p];
        }
    return out;
}

}  // namespace

int main(int argc, char** argv)
{
    if (argc < 4 || argc > 5) {
        std::cerr << "usage: run_unet WEIGHTS.tza INPUT.bin OUTPUT.bin [NTHREADS]\n";
        return 2;
    }
    std::string error;
    mcdenoise::UNet net;
    HwcTensor input;
    if (!net.load(argv[1], error) || !read_tensor(argv[2], input, error)) {
        std::cerr << "run_unet: " << error << "\n";
        return 1;
    }
    if (input.channels != net.layout().input_channels) {
        std::cerr << "run_unet: " << argv[2] << " has " << input.channels << " channels; "
                  << argv[1] << " takes " << net.layout().input_channels << "\n";
        return 1;
    }
    const size_t pixels = size_t(input.height) * size_t(input.width);
    const auto planes   = transpose(input.values, pixels, size_t(input.channels), true);
    std::vector<float> output(pixels * 3);
    if (!net.run(planes.data(), input.height, input.width, output.data(),
                 argc == 5 ? std::stoi(argv[4]) : 0, error)) {
        std::cerr << "run_unet: " << error << "\n";
        return 1;
    }
    HwcTensor result { input.height, input.width, 3, transpose(output, pixels, 3, false) };
    if (!write_tensor(argv[3], result)) {
        std::cerr << "run_unet: cannot write " << argv[3] << "\n";
        return 1;
    }
    return 0;
}
