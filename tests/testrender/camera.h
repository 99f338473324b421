// camera.h: the thin-lens camera. A pinhole when the aperture is 0; with an
// aperture, points on the focus plane are sharp and others are defocused.
#pragma once

#include "math.h"

namespace testrender {

struct CameraParams {
    Vec3 eye { 0, 0, 0 };
    Vec3 look_at { 0, 0, -1 };
    Vec3 up { 0, 1, 0 };
    double vfov_degrees = 40;     ///< full vertical field of view
    double aperture_radius = 0;   ///< lens radius in world units; 0 is a pinhole
    double focus_distance = 1;    ///< distance along the view axis that is sharp
};

class Camera {
public:
    Camera(const CameraParams& params, int width, int height);

    /// The ray through film position (fx, fy) in pixels (x right, y down,
    /// pixel (i, j) covers [i, i+1) x [j, j+1)) and lens sample (lu, lv) in
    /// [0,1)^2. The direction is unit length.
    Ray generate(double fx, double fy, double lu, double lv) const;

    /// The ray from the lens center through film position (fx, fy): the
    /// ray the geometric AOVs (depth, id, reflid) are taken from.
    Ray center_ray(double fx, double fy) const;

    /// The film position (in pixels) a world point projects to through the
    /// lens center; false if it is behind the camera.
    bool project(const Vec3& p, double& fx, double& fy) const;

    /// The film position a direction at infinity projects to (where a ray
    /// along `dir` from the lens center crosses the film); false if it
    /// points behind the camera.
    bool project_direction(const Vec3& dir, double& fx, double& fy) const;

    const CameraParams& params() const { return params_; }

private:
    Vec3 pinhole_dir(double fx, double fy) const;

    CameraParams params_;
    int width_, height_;
    Vec3 forward_, right_, up_;
    double half_h_, half_w_;
};

}  // namespace testrender
