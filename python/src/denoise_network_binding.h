// denoise_network_binding.h: binds `mcdenoise.denoise_network`, the trained
// denoiser (OIDN 2.x's networks on mcdenoise's engine).
#pragma once

#include <pybind11/pybind11.h>

namespace mcdpy {

namespace py = pybind11;

/// Adds `denoise_network(beauty, guides=None, *, neighbours=None,
/// quality="high", prefilter_guides=True, memory_limit=0, weights_dir="",
/// roi, nthreads)`, the `NetworkFrame` class and
/// `prepare_network_frame(beauty, guides=None, *, quality, ...)` to
/// `module`.
void bind_denoise_network(py::module_& module);

}  // namespace mcdpy
