// operations.cpp: the table of bound library operations. Exposing a filter
// is one entry: its name, its value form, and its arguments after the
// beauty with the header's defaults (roi and nthreads are added).
#include "operations.h"

#include "operation.h"

#include <mcdenoise/mcdenoise.h>

namespace mcdpy {

namespace mcd = mcdenoise;
using py::arg;

void bind_operations(py::module_& m)
{
    def_operation(m, "mean", mcd::mean, arg("beauty"), arg("size") = 3);
    def_operation(m, "median", mcd::median, arg("beauty"), arg("size") = 3);
    def_operation(m, "gaussian", mcd::gaussian, arg("beauty"), arg("size") = 3);
    def_operation(m, "object_mean", mcd::object_mean, arg("beauty"), arg("object_id"), arg("size") = 3);
    def_operation(m, "object_median", mcd::object_median, arg("beauty"), arg("object_id"), arg("size") = 3);
    def_operation(m, "object_gaussian", mcd::object_gaussian, arg("beauty"), arg("object_id"), arg("size") = 3);
    def_operation(m, "brdf_mean", mcd::brdf_mean, arg("beauty"), arg("object_id"), arg("reflect_id"),
                  arg("size") = 3);
    def_operation(m, "brdf_gaussian", mcd::brdf_gaussian, arg("beauty"), arg("object_id"), arg("reflect_id"),
                  arg("size") = 3);
    def_operation(m, "brdf_median", mcd::brdf_median, arg("beauty"), arg("object_id"), arg("reflect_id"),
                  arg("size") = 3);
    def_operation(m, "normal_mean", mcd::normal_mean, arg("beauty"), arg("object_id"), arg("normal"),
                  arg("size") = 3);
    def_operation(m, "normal_gaussian", mcd::normal_gaussian, arg("beauty"), arg("object_id"), arg("normal"),
                  arg("size") = 3);
    def_operation(m, "dof_focus_map", mcd::dof_focus_map, arg("depth"), arg("levels"), arg("focus_level"),
                  arg("depth_near") = 0.0f, arg("depth_far") = 0.0f);
    def_operation(m, "dof", mcd::dof, arg("beauty"), arg("object_id"), arg("depth"), arg("levels"),
                  arg("focus_level"), arg("depth_near") = 0.0f, arg("depth_far") = 0.0f);

    def_operation(m, "compare_images", mcd::compare_images, arg("result"), arg("reference"));
    def_operation(m, "rel_mse", mcd::rel_mse, arg("result"), arg("reference"));
    def_operation(m, "mse", mcd::mse, arg("result"), arg("reference"));
    def_operation(m, "psnr", mcd::psnr, arg("result"), arg("reference"));
    def_operation(m, "ssim", mcd::ssim, arg("result"), arg("reference"));
}

}  // namespace mcdpy
