// denoise_binding.h: binds `denoise` in both its library forms: one frame
// (denoise.h), or a frame with its neighbouring frames (temporal.h).
#pragma once

#include <pybind11/pybind11.h>

namespace mcdpy {

namespace py = pybind11;

/// Adds `denoise(beauty, guides=None, neighbours=None, roi, nthreads)` to
/// `module`: with `neighbours`, a list of (offset, beauty, guides) or
/// (offset, PreparedFrame) tuples, the cross-frame form; and
/// `prepare_frame(beauty, guides=None, nthreads)`, giving a PreparedFrame.
void bind_denoise(py::module_& module);

}  // namespace mcdpy
