// driver.h: binds the parts of mcdtool the batch module runs frames with.
#pragma once

#include <pybind11/pybind11.h>

namespace mcdpy {

namespace py = pybind11;

/// Adds mcdtool's frame runner, frame lists and frame paths to `module`.
void bind_driver(py::module_& module);

}  // namespace mcdpy
