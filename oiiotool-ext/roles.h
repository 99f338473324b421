// roles.h: the guide roles (docs/filters.md, "Guide roles"): the one vocabulary
// shared by --aov ROLE=..., the command table and the C++ argument names.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace mcdtool {

/// A guide image a command may need beside the beauty.
enum class Role { id, reflid, normal, depth, albedo, variance, half_a, half_b, motion };

/// Everything the driver knows about one role.
struct RoleInfo {
    Role role;
    const char* name;          ///< as typed in --aov ROLE=FILE
    const char* argument;      ///< the C++ / Python argument name
    int min_channels;          ///< 0 with like_beauty
    int max_channels;          ///< 0 with like_beauty
    bool like_beauty;          ///< needs exactly the beauty's channel count
    const char* what;          ///< one-line description for help and errors
    std::vector<const char*> pass_names;  ///< names to look for, preferred first
};

/// Every role, in the order of docs/filters.md's guide roles table.
const std::vector<RoleInfo>& role_table();

/// The entry for `role`.
const RoleInfo& role_info(Role role);

/// The entry named `name` (as typed after --aov), or nullptr.
const RoleInfo* find_role(std::string_view name);

/// "3", "3 or 1" or "like beauty": the channel counts `info` accepts.
std::string channel_count_text(const RoleInfo& info);

/// True if a guide with `nchannels` channels fits `info` for a beauty with
/// `beauty_channels` channels.
bool channel_count_ok(const RoleInfo& info, int nchannels, int beauty_channels);

}  // namespace mcdtool
