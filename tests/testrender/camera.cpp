// camera.cpp: thin-lens ray generation (concentric disk lens sampling) and
// the inverse projection the tests use to find where an object appears.
#include "camera.h"

namespace testrender {

namespace {

/// Shirley and Chiu's concentric map from [0,1)^2 to the unit disk.
void concentric_disk(double u, double v, double& dx, double& dy)
{
    const double a = 2 * u - 1, b = 2 * v - 1;
    if (a == 0 && b == 0) {
        dx = dy = 0;
        return;
    }
    double r, phi;
    if (std::abs(a) > std::abs(b)) {
        r = a;
        phi = (pi / 4) * (b / a);
    } else {
        r = b;
        phi = (pi / 2) - (pi / 4) * (a / b);
    }
    dx = r * std::cos(phi);
    dy = r * std::sin(phi);
}

}  // namespace

Camera::Camera(const CameraParams& params, int width, int height)
    : params_(params), width_(width), height_(height)
{
    forward_ = normalize(params.look_at - params.eye);
    right_ = normalize(cross(forward_, params.up));
    up_ = cross(right_, forward_);
    half_h_ = std::tan(params.vfov_degrees * pi / 360.0);
    half_w_ = half_h_ * double(width) / double(height);
}

Vec3 Camera::pinhole_dir(double fx, double fy) const
{
    const double sx = (2 * fx / width_ - 1) * half_w_;
    const double sy = (1 - 2 * fy / height_) * half_h_;
    return forward_ + right_ * sx + up_ * sy;  // not normalised: forward component is 1
}

Ray Camera::center_ray(double fx, double fy) const
{
    return { params_.eye, normalize(pinhole_dir(fx, fy)) };
}

Ray Camera::generate(double fx, double fy, double lu, double lv) const
{
    const Vec3 d = pinhole_dir(fx, fy);
    if (params_.aperture_radius <= 0)
        return { params_.eye, normalize(d) };
    // d has unit forward component, so the focus plane is at d * focus_distance.
    const Vec3 focus_point = params_.eye + d * params_.focus_distance;
    double dx, dy;
    concentric_disk(lu, lv, dx, dy);
    const Vec3 origin = params_.eye
                        + (right_ * dx + up_ * dy) * params_.aperture_radius;
    return { origin, normalize(focus_point - origin) };
}

bool Camera::project(const Vec3& p, double& fx, double& fy) const
{
    return project_direction(p - params_.eye, fx, fy);
}

bool Camera::project_direction(const Vec3& d, double& fx, double& fy) const
{
    const double depth = dot(d, forward_);
    if (depth <= 0)
        return false;
    const double sx = dot(d, right_) / depth / half_w_;
    const double sy = dot(d, up_) / depth / half_h_;
    fx = (sx + 1) * 0.5 * width_;
    fy = (1 - sy) * 0.5 * height_;
    return true;
}

}  // namespace testrender
