// operations.cpp: the table of bound library operations. Exposing a filter
// is one entry: its name, its value form, and its arguments after the
// beauty with the header's named defaults (roi and nthreads are added). The
// classes the arguments and results use (ImageComparison, FeatureSigmas)
// are bound first, in module.cpp.
#include "operations.h"

#include "denoise_binding.h"
#include "denoise_layers.h"
#include "denoise_network_binding.h"
#include "operation.h"

#include <mcdenoise/mcdenoise.h>

namespace mcdpy {

namespace mcd = mcdenoise;
using py::arg;

void bind_operations(py::module_& m)
{
    const int size = mcd::default_window_size;
    def_operation(m, "mean", mcd::mean, arg("beauty"), arg("size") = size);
    def_operation(m, "median", mcd::median, arg("beauty"), arg("size") = size);
    def_operation(m, "gaussian", mcd::gaussian, arg("beauty"), arg("size") = size);
    def_operation(m, "object_mean", mcd::object_mean, arg("beauty"), arg("object_id"), arg("size") = size);
    def_operation(m, "object_median", mcd::object_median, arg("beauty"), arg("object_id"), arg("size") = size);
    def_operation(m, "object_gaussian", mcd::object_gaussian, arg("beauty"), arg("object_id"), arg("size") = size);
    def_operation(m, "brdf_mean", mcd::brdf_mean, arg("beauty"), arg("object_id"), arg("reflect_id"),
                  arg("size") = size);
    def_operation(m, "brdf_gaussian", mcd::brdf_gaussian, arg("beauty"), arg("object_id"), arg("reflect_id"),
                  arg("size") = size);
    def_operation(m, "brdf_median", mcd::brdf_median, arg("beauty"), arg("object_id"), arg("reflect_id"),
                  arg("size") = size);
    def_operation(m, "normal_mean", mcd::normal_mean, arg("beauty"), arg("object_id"), arg("normal"),
                  arg("size") = size);
    def_operation(m, "normal_gaussian", mcd::normal_gaussian, arg("beauty"), arg("object_id"), arg("normal"),
                  arg("size") = size);
    def_operation(m, "dof_focus_map", mcd::dof_focus_map, arg("depth"), arg("levels"), arg("focus_level"),
                  arg("depth_near") = mcd::dof_image_depth_range, arg("depth_far") = mcd::dof_image_depth_range);
    def_operation(m, "dof", mcd::dof, arg("beauty"), arg("object_id"), arg("depth"), arg("levels"),
                  arg("focus_level"), arg("depth_near") = mcd::dof_image_depth_range,
                  arg("depth_far") = mcd::dof_image_depth_range);

    def_operation(m, "cross_bilateral", mcd::cross_bilateral, arg("beauty"), arg("guides"),
                  arg("size") = mcd::default_cross_bilateral_size,
                  arg("sigma_spatial") = mcd::default_cross_bilateral_sigma_spatial,
                  arg("sigma_color") = mcd::default_cross_bilateral_sigma_color,
                  arg("sigmas") = mcd::FeatureSigmas());
    def_operation(m, "atrous", mcd::atrous, arg("beauty"), arg("guides"),
                  arg("iterations") = mcd::default_atrous_iterations,
                  arg("sigma_luminance") = mcd::default_atrous_sigma_luminance,
                  arg("sigmas") = mcd::FeatureSigmas());
    def_operation(m, "nlmeans", mcd::nlmeans, arg("beauty"), arg("guides"),
                  arg("search_radius") = mcd::default_nlmeans_search_radius,
                  arg("patch_radius") = mcd::default_nlmeans_patch_radius,
                  arg("strength") = mcd::default_nlmeans_strength, arg("sigmas") = mcd::FeatureSigmas());
    def_operation(m, "clamp_fireflies", mcd::clamp_fireflies, arg("beauty"), arg("guides"),
                  arg("factor") = mcd::default_firefly_factor, arg("radius") = mcd::default_firefly_radius);
    bind_denoise(m);         // one frame, or with its neighbours (denoise_binding.cpp)
    bind_denoise_layers(m);  // with light passes: an overload of denoise, and denoise_layers
    bind_denoise_network(m);  // the trained denoiser (denoise_network_binding.cpp)
    def_operation(m, "demodulate", mcd::demodulate, arg("beauty"), arg("albedo"),
                  arg("epsilon") = mcd::default_demodulate_epsilon);
    def_operation(m, "remodulate", mcd::remodulate, arg("filtered"), arg("albedo"),
                  arg("epsilon") = mcd::default_demodulate_epsilon);

    def_operation(m, "compare_images", mcd::compare_images, arg("result"), arg("reference"));
    def_operation(m, "rel_mse", mcd::rel_mse, arg("result"), arg("reference"));
    def_operation(m, "mse", mcd::mse, arg("result"), arg("reference"));
    def_operation(m, "psnr", mcd::psnr, arg("result"), arg("reference"));
    def_operation(m, "ssim", mcd::ssim, arg("result"), arg("reference"));
}

}  // namespace mcdpy
