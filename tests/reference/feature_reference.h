// feature_reference.h: an independent, deliberately plain implementation of
// the feature-guided filters (features.h, cross_bilateral.h, atrous.h,
// nlmeans.h, demodulate.h) for the tests: double precision, every tap
// visited one by one, whole-image iterates, no code shared with the library.
#pragma once

#include "reference/spec_reference.h"

#include <vector>

namespace featref {

/// The guides as double images; nullptr when absent. Pixels outside a
/// guide's data window read as "no value" (features.h).
struct Guides {
    const spec::Image* object_id = nullptr;
    const spec::Image* normal    = nullptr;
    const spec::Image* depth     = nullptr;
    const spec::Image* albedo    = nullptr;
    const spec::Image* variance  = nullptr;
};

/// Feature fall-offs; <= 0 leaves a feature out.
struct Sigmas {
    double albedo = 0.1, normal = 0.3, depth = 0.1;
};

/// Each returns roi.width() * roi.height() * roi.nchannels() values, pixel
/// by pixel, channels interleaved, and counts windows with no finite value
/// (per channel) in `empty` when given.
std::vector<double> cross_bilateral(const spec::Image& beauty, const Guides& guides, int size,
                                    double sigma_spatial, double sigma_color,
                                    const Sigmas& sigmas, const OIIO::ROI& roi,
                                    long* empty = nullptr);

std::vector<double> atrous(const spec::Image& beauty, const Guides& guides, int iterations,
                           double sigma_luminance, const Sigmas& sigmas, const OIIO::ROI& roi,
                           long* empty = nullptr);

std::vector<double> nlmeans(const spec::Image& beauty, const Guides& guides, int search_radius,
                            int patch_radius, double strength, const Sigmas& sigmas,
                            const OIIO::ROI& roi, long* empty = nullptr);

/// demodulate (`divide`) or remodulate.
std::vector<double> modulate(const spec::Image& beauty, const spec::Image& albedo,
                             double epsilon, bool divide, const OIIO::ROI& roi);

}  // namespace featref
