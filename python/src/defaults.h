// defaults.h: binds the library's named defaults and guide vocabulary as
// module constants.
#pragma once

#include <pybind11/pybind11.h>

namespace mcdpy {

namespace py = pybind11;

/// Adds the default parameters of the library's headers (`default_*`,
/// `dof_image_depth_range`) to `module` under their C++ names, so Python
/// code and tests read them instead of repeating the numbers; and the
/// guide vocabulary of features.h: `guide_fields` (the names a `guides`
/// dict takes) and `guides_used` (function name -> the guides it uses).
void bind_defaults(py::module_& module);

}  // namespace mcdpy
