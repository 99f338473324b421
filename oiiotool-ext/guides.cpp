// guides.cpp: guide assembly, channel-count and coverage checks.
#include "guides.h"

#include "cryptomatte.h"
#include "error.h"
#include "output.h"

#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/strutil.h>

#include <cstdio>

namespace mcdtool {

using OIIO::Strutil::fmt::format;

namespace {

/// "x [0,64) y [0,48)": a data window for messages.
std::string window_text(const OIIO::ROI& roi)
{
    return format("x [{},{}) y [{},{})", roi.xbegin, roi.xend, roi.ybegin, roi.yend);
}

/// Throws unless `nchannels` suits `info`.
void require_channel_count(const RoleInfo& info, int nchannels, int beauty_channels,
                           const std::string& channels, const std::string& context)
{
    if (channel_count_ok(info, nchannels, beauty_channels))
        return;
    std::string need = info.like_beauty ? format("{} (like the beauty)", beauty_channels)
                                        : channel_count_text(info);
    throw RunError(format("{} : the {} guide needs {} channel(s), got {} ({}); pick them with :CHANNELS",
                          context, info.name, need, nchannels, channels));
}

/// True when channels `indices` of `spec` give the `role` guide as
/// Cryptomatte hashes.
bool cryptomatte_guide(const ImageSpec& spec, Role role, const std::vector<int>& indices)
{
    return role == Role::id && indices.size() == 1 && is_cryptomatte_id_channel(spec, indices[0]);
}

/// Channels `indices` of `file` (read by `files`) as the guide of `role`:
/// Cryptomatte hashes and ids stored as integers as whole-number ids,
/// anything else as float.
ImageBuf guide_image(ImageFiles& files, const ImageBuf& file, Role role, const std::vector<int>& indices)
{
    if (cryptomatte_guide(file.spec(), role, indices))
        return cryptomatte_ids(file, indices[0]);
    const bool ids = role == Role::id || role == Role::reflid;
    if (ids && indices.size() == 1 && stored_as_integers(file, indices[0]))
        return files.integer_channels(file).at(indices[0]);
    return extract_channels(file, indices);
}

/// "render.exr: N.X,N.Y,N.Z": where a guide came from, for -v.
std::string guide_source(const std::string& path, const ImageSpec& spec, Role role, const std::vector<int>& indices)
{
    return format("{}: {}{}", path, channel_names(spec, indices),
                  cryptomatte_guide(spec, role, indices) ? " (Cryptomatte ids)" : "");
}

/// Throws unless the guide file `file` has `input`'s display window (a
/// guide rendered at another resolution would be cropped, not scaled).
void require_same_display_window(const ImageBuf& file, const ImageBuf& input, const std::string& context)
{
    OIIO::ROI g = file.roi_full();
    OIIO::ROI b = input.roi_full();
    if (g.xbegin == b.xbegin && g.ybegin == b.ybegin && g.xend == b.xend && g.yend == b.yend)
        return;
    throw RunError(format("{} : display window {} x {} ({}) differs from the beauty's {} x {} ({}): render "
                          "the guide at the beauty's resolution", context, g.width(), g.height(), window_text(g),
                          b.width(), b.height(), window_text(b)));
}

/// Warns when the id guide that `used` commands need is one value
/// everywhere (Blender's default pass index 0): the object filters then
/// work as their plain versions.
void warn_constant_ids(const GuideImages& guides, const std::set<Role>& used)
{
    auto ids = guides.images.find(Role::id);
    if (ids == guides.images.end() || !used.count(Role::id))
        return;
    OIIO::ImageBufAlgo::PixelStats stats = OIIO::ImageBufAlgo::computePixelStats(ids->second);
    if (stats.min.empty() || stats.min[0] != stats.max[0])
        return;
    std::fprintf(stderr,
                 "mcdtool WARNING: the id guide (%s) is %g everywhere: the object filters work as their plain "
                 "versions; give the objects ids (Blender: Object Properties > Relations > Pass Index) or "
                 "use a Cryptomatte object layer\n",
                 guides.sources.at(Role::id).c_str(), double(stats.min[0]));
}

}  // namespace

std::set<Role> roles_used(const std::vector<Step>& steps, bool across_frames)
{
    std::set<Role> used;
    if (across_frames)
        used.insert(Role::motion);
    for (const Step& step : steps)
        if (step.command) {
            used.insert(step.command->roles.begin(), step.command->roles.end());
            used.insert(step.command->optional_roles.begin(), step.command->optional_roles.end());
        }
    return used;
}

void require_coverage(const ImageBuf& guide, const ImageBuf& beauty, const std::string& context)
{
    OIIO::ROI g = guide.roi();
    OIIO::ROI b = beauty.roi();
    if (g.xbegin <= b.xbegin && g.ybegin <= b.ybegin && g.xend >= b.xend && g.yend >= b.yend)
        return;
    throw RunError(format("{} : data window {} does not cover the beauty's data window {}", context,
                          window_text(g), window_text(b)));
}

GuideImages load_guides(const ImageBuf& input, const std::string& input_path, const Discovery& found,
                   const std::vector<AovRequest>& aovs, const std::set<Role>& used,
                   const PathForFrame& frame_path_of, ImageFiles& files)
{
    GuideImages guides;
    int beauty_channels = int(found.beauty.size());
    for (const auto& [role, indices] : found.roles) {
        if (used.count(role))
            guides.images[role] = guide_image(files, input, role, indices);
        guides.sources[role] = guide_source(input_path, input.spec(), role, indices);
    }
    for (const AovRequest& aov : aovs) {
        const RoleInfo& info = role_info(aov.role);
        std::string context = "--aov " + aov.typed;
        std::string path = frame_path_of(aov.file);
        const ImageBuf& file = same_file(path, input_path) ? input : files.get(path, context);
        std::vector<int> indices;
        if (aov.channels.empty()) {
            for (int c = 0; c < file.nchannels(); ++c)
                indices.push_back(c);
        } else {
            indices = select_channels(file.spec(), aov.channels, path, context);
        }
        require_channel_count(info, int(indices.size()), beauty_channels, channel_names(file.spec(), indices),
                              context);
        require_same_display_window(file, input, context);
        ImageBuf guide = guide_image(files, file, aov.role, indices);
        require_coverage(guide, input, context);
        guides.images[aov.role] = std::move(guide);
        guides.sources[aov.role] = guide_source(path, file.spec(), aov.role, indices);
    }
    warn_constant_ids(guides, used);
    return guides;
}

void require_guides(const Command& command, const GuideImages& guides, const std::string& input_path,
                    const ImageSpec& input_spec, const Discovery& found)
{
    for (Role role : command.roles) {
        if (guides.images.count(role))
            continue;
        const RoleInfo& info = role_info(role);
        std::vector<std::string> looked;
        for (const char* pass : info.pass_names)
            looked.push_back(found.layer.empty() ? pass : found.layer + "." + pass);
        throw RunError(format("--{} : needs the {} guide ({}); {} has none of {} (channels: {}); "
                              "give --aov {}=FILE[:CHANNELS]",
                              command.name, info.name, info.what, input_path, OIIO::Strutil::join(looked, ", "),
                              all_channel_names(input_spec), info.name));
    }
}

}  // namespace mcdtool
