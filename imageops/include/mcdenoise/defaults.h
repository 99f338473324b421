// defaults.h: the default parameters of every filter, written once. The
// headers' declarations, mcdtool's command table, the Python module (which
// exposes them as mcdenoise.default_*) and the tests read them from here.
#pragma once

namespace mcdenoise {

// The window filters of simple.h, object.h, brdf.h and normal.h.
/// The window side every window filter takes when none is given.
constexpr int default_window_size = 3;

// dof.h
/// The `depth_near` and `depth_far` of `dof` and `dof_focus_map` when none
/// are given: no explicit range, the image's finite depths span the levels.
constexpr float dof_image_depth_range = 0.0f;

// cross_bilateral.h
/// `cross_bilateral`'s window side when none is given.
constexpr int default_cross_bilateral_size = 7;
/// `cross_bilateral`'s spatial fall-off in pixels when none is given.
constexpr float default_cross_bilateral_sigma_spatial = 2.0f;
/// `cross_bilateral`'s colour fall-off when none is given: colour left out.
constexpr float default_cross_bilateral_sigma_color = 0.0f;

// atrous.h
/// `atrous`' pass count when none is given.
constexpr int default_atrous_iterations = 5;
/// `atrous`' luminance edge-stopping scale when none is given.
constexpr float default_atrous_sigma_luminance = 4.0f;

// nlmeans.h
/// `nlmeans`' search radius when none is given (a 15 x 15 window).
constexpr int default_nlmeans_search_radius = 7;
/// `nlmeans`' patch radius when none is given (3 x 3 patches).
constexpr int default_nlmeans_patch_radius = 1;
/// `nlmeans`' strength when none is given.
constexpr float default_nlmeans_strength = 0.45f;

// fireflies.h
/// `clamp_fireflies`' factor when none is given.
constexpr float default_firefly_factor = 2.0f;
/// `clamp_fireflies`' window radius when none is given (5 x 5 windows).
constexpr int default_firefly_radius = 2;

// demodulate.h
/// The epsilon `demodulate` and `remodulate` add to the albedo when none is
/// given.
constexpr float default_demodulate_epsilon = 0.01f;

}  // namespace mcdenoise
