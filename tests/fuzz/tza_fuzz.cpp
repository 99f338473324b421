// tza_fuzz.cpp: libFuzzer target for the .tza reader (network/tza.h): the
// input bytes are parsed in memory as a weight file. Invariants: it never
// crashes; a failure leaves no tensors and names the source in its error;
// a success gives every tensor 1 to 4 dimensions, a layout of as many
// characters, and as many values as the product of its dimensions.
#include "fuzz_dir.h"
#include "network/tza.h"

#include <cstddef>
#include <cstdint>
#include <string>

namespace {

/// The name the input is parsed under, which every error starts with.
const std::string source = "fuzz.tza";

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    mcdenoise::TensorMap tensors;
    std::string error;
    if (!mcdenoise::parse_tza(data, size, source, tensors, error)) {
        mcdfuzz::require(tensors.empty(), "a failed parse left tensors");
        mcdfuzz::require(error.rfind(source + ": ", 0) == 0,
                         "the error names the source: " + error);
        return 0;
    }
    for (const auto& [name, t] : tensors) {
        mcdfuzz::require(name == t.name && !name.empty(), "the tensor is filed under its name");
        mcdfuzz::require(!t.dims.empty() && int(t.dims.size()) <= mcdenoise::tza_max_dims,
                         "1 to 4 dimensions: " + name);
        mcdfuzz::require(t.layout.size() == t.dims.size(),
                         "a layout character per dimension: " + name);
        size_t count = 1;
        for (int d : t.dims) {
            mcdfuzz::require(d > 0, "dimensions are positive: " + name);
            count *= size_t(d);
        }
        mcdfuzz::require(t.values.size() == count, "values = product of the dimensions: " + name);
    }
    return 0;
}
