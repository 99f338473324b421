// defaults.cpp: the library's named defaults as constants of the module
// (mcdenoise.default_nlmeans_strength, ...), the values the bound functions
// take when an argument is left out, and its guide vocabulary (the names of
// the `guides` keys, the guides each feature-guided function uses).
#include "defaults.h"

#include <mcdenoise/mcdenoise.h>

namespace mcdpy {

namespace mcd = mcdenoise;

namespace {

/// The names of the `Guides` fields in `guides`, in declaration order.
py::tuple guide_names(mcd::GuideMask guides)
{
    py::list names;
    for (const mcd::GuideField& field : mcd::guide_fields)
        if (guides & field.bit)
            names.append(field.name);
    return py::tuple(names);
}

}  // namespace

void bind_defaults(py::module_& m)
{
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
    m.attr("guide_fields") = guide_names(~0u);
    py::dict used;
    used["cross_bilateral"] = guide_names(mcd::cross_bilateral_guides);
    used["atrous"] = guide_names(mcd::atrous_guides);
    used["nlmeans"] = guide_names(mcd::nlmeans_guides);
    used["clamp_fireflies"] = guide_names(mcd::clamp_fireflies_guides);
    used["denoise"] = guide_names(mcd::denoise_guides);
    used["denoise_network"] = guide_names(mcd::denoise_network_guides);
    m.attr("guides_used") = used;
}

}  // namespace mcdpy
