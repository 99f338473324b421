// shot_figures.h: the figures of docs/temporal.md: each method (raw,
// per-frame denoise, the warped-average baseline, the cross-frame denoise
// with and without motion) measured on the three shots of the shot set.
#pragma once

#include <OpenImageIO/imagebuf.h>

#include <string>
#include <vector>

namespace testimg {

/// One method on one shot.
struct MethodFigures {
    std::vector<double> frame_rel_mse;  ///< per evaluated frame
    double rel_mse  = 0;                ///< their mean
    double temporal = 0;                ///< mean temporal error (moving shots)
    double flicker  = 0;                ///< static shot
    double region   = 0;                ///< relMSE on the shot's region (see below)
};

/// The methods on one shot, and the result images of the last evaluated
/// frame (for pictures).
struct ShotFigures {
    std::string shot, error;
    int n = 0;             ///< neighbours each side
    std::vector<int> evaluated;  ///< frame numbers with a reference
    MethodFigures raw, per_frame, baseline, cross, cross_still;
    std::vector<OIIO::ImageBuf> pictures;  ///< raw, per-frame, baseline, cross, reference
};

/// Method names in the order of `ShotFigures`' members.
const std::vector<std::string>& method_names();
/// The members of `f` in that order.
std::vector<const MethodFigures*> methods(const ShotFigures& f);

/// shot_static, frames 0..7, N = 3, every frame evaluated; region: none.
ShotFigures static_figures(const std::string& dir);
/// shot_truck, frames 0..6, N = 2, frames 2..4 evaluated; region: the
/// disoccluded pixels.
ShotFigures truck_figures(const std::string& dir);
/// shot_object, frames 0..4, N = 2, frame 2 evaluated; region: the pixels
/// the object and its shadow leave behind.
ShotFigures object_figures(const std::string& dir);

/// One pixel's colour channel `c` over the static shot's frames per method
/// (raw, per-frame, cross-frame) and the reference, rows of
/// `frame,raw,per_frame,cross,reference`, as CSV text.
std::string static_pixel_csv(const std::string& dir, int x, int y, int c);

}  // namespace testimg
