// denoise_layers.h: binds the `layers=` form of `mcdenoise.denoise`.
#pragma once

#include <pybind11/pybind11.h>

namespace mcdpy {

namespace py = pybind11;

/// Adds the overload `denoise(beauty, *, layers, guides=None, roi, nthreads)`
/// to `module` (after the plain `denoise`) and `denoise_layers` under its
/// library name.
void bind_denoise_layers(py::module_& module);

}  // namespace mcdpy
