// defaults.cpp: the library's named defaults as constants of the module
// (mcdenoise.default_nlmeans_strength, ...), the values the bound functions
// take when an argument is left out.
#include "defaults.h"

#include <mcdenoise/mcdenoise.h>

namespace mcdpy {

void bind_defaults(py::module_& m)
{
    namespace mcd = mcdenoise;
    m.attr("default_window_size") = mcd::default_window_size;
    m.attr("dof_image_depth_range") = mcd::dof_image_depth_range;
    m.attr("default_cross_bilateral_size") = mcd::default_cross_bilateral_size;
    m.attr("default_cross_bilateral_sigma_spatial") = mcd::default_cross_bilateral_sigma_spatial;
    m.attr("default_cross_bilateral_sigma_color") = mcd::default_cross_bilateral_sigma_color;
    m.attr("default_atrous_iterations") = mcd::default_atrous_iterations;
    m.attr("default_atrous_sigma_luminance") = mcd::default_atrous_sigma_luminance;
    m.attr("default_nlmeans_search_radius") = mcd::default_nlmeans_search_radius;
    m.attr("default_nlmeans_patch_radius") = mcd::default_nlmeans_patch_radius;
    m.attr("default_nlmeans_strength") = mcd::default_nlmeans_strength;
    m.attr("default_firefly_factor") = mcd::default_firefly_factor;
    m.attr("default_firefly_radius") = mcd::default_firefly_radius;
    m.attr("default_demodulate_epsilon") = mcd::default_demodulate_epsilon;
    m.attr("max_window_size") = mcd::max_window_size;
}

}  // namespace mcdpy
