// operations.h: binds every library filter and metric.
#pragma once

#include <pybind11/pybind11.h>

namespace mcdpy {

namespace py = pybind11;

/// Adds every filter and metric of libmcdenoise to `module`, with the
/// library's names, argument names, defaults and doc comments.
void bind_operations(py::module_& module);

}  // namespace mcdpy
