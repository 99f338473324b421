// roles.cpp: the guide role table and its lookups.
#include "roles.h"

#include <OpenImageIO/strutil.h>

namespace mcdtool {

const std::vector<RoleInfo>& role_table()
{
    // Pass names: testrender's first, then Blender Cycles' (its multilayer
    // EXR pass names: IndexOB, Normal, Depth and the Denoising passes), then those of RenderMan's denoise AOVs (zfiltered; mse,
    // the variance of the pixel's mean) and Arnold's (denoise_albedo, and
    // diffuse_albedo before Arnold 6); matching ignores case and looks only
    // in the beauty's view layer. Motion is Cycles' Vector pass convention
    // (docs/temporal.md): X,Y the film offset to the pixel's position in the
    // previous frame, Z,W the offset from its position in the next frame,
    // in pixels, y up; testrender writes the same as motion.X,Y,Z,W.
    static const std::vector<RoleInfo> table = {
        { Role::id, "id", "object_id", 1, 1, false, "object id of the first hit",
          { "id", "IndexOB", "object_id", "objectid" } },
        { Role::reflid, "reflid", "reflect_id", 1, 1, false,
          "object id seen in a specular pixel's mirror reflection, negative if none",
          { "reflid", "reflect_id" } },
        { Role::normal, "normal", "normal", 3, 3, false, "first-hit normal",
          { "N", "Denoising Normal", "Normal" } },
        { Role::depth, "depth", "depth", 1, 1, false,
          "first-hit distance (>= 1e9, e.g. Cycles' 1e10, is background)",
          { "Z", "Depth", "Denoising Depth", "zfiltered" } },
        { Role::albedo, "albedo", "albedo", 1, 3, false,
          "first non-specular hit's reflectance",
          { "albedo", "Denoising Albedo", "denoise_albedo", "diffuse_albedo" } },
        { Role::variance, "variance", "variance", 1, 3, false,
          "variance of the pixel estimate", { "var", "variance", "mse" } },
        { Role::half_a, "half_a", "half_a", 0, 0, true,
          "half-sample estimate of the beauty (first half)", { "A", "half_a" } },
        { Role::half_b, "half_b", "half_b", 0, 0, true,
          "half-sample estimate of the beauty (second half)", { "B", "half_b" } },
        { Role::motion, "motion", "motion", 4, 4, false,
          "screen-space motion in pixels, y up: X,Y to the previous frame, Z,W from the next (Cycles' Vector pass)",
          { "motion", "Vector" } },
    };
    return table;
}

const RoleInfo& role_info(Role role)
{
    for (const RoleInfo& info : role_table())
        if (info.role == role)
            return info;
    return role_table().front();  // unreachable: every Role is in the table
}

const RoleInfo* find_role(std::string_view name)
{
    for (const RoleInfo& info : role_table())
        if (name == info.name)
            return &info;
    return nullptr;
}

std::string channel_count_text(const RoleInfo& info)
{
    if (info.like_beauty)
        return "as many as the beauty";
    if (info.min_channels == info.max_channels)
        return std::to_string(info.min_channels);
    return OIIO::Strutil::fmt::format("{} or {}", info.max_channels, info.min_channels);
}

bool channel_count_ok(const RoleInfo& info, int nchannels, int beauty_channels)
{
    if (info.like_beauty)
        return nchannels == beauty_channels;
    return nchannels == info.min_channels || nchannels == info.max_channels;
}

}  // namespace mcdtool
