// frame_window.cpp: holding, dropping and checking the frames of a
// --temporal run.
#include "frame_window.h"

#include "error.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/strutil.h>

#include <cstdio>
#include <cstdlib>

namespace mcdtool {

using OIIO::Strutil::fmt::format;

namespace {

/// "x [0,64) y [0,48)".
std::string window_text(const OIIO::ROI& roi)
{
    return format("x [{},{}) y [{},{})", roi.xbegin, roi.xend, roi.ybegin, roi.yend);
}

/// "normal, depth": the guide roles present in `guides` besides motion
/// (which a neighbour may lack: temporal.h repeats the last vector known).
std::string role_list(const GuideImages& guides)
{
    std::vector<std::string> names;
    for (const auto& [role, image] : guides.images)
        if (role != Role::motion)
            names.push_back(role_info(role).name);
    return names.empty() ? "none" : OIIO::Strutil::join(names, ", ");
}

/// Throws unless `neighbour` can be denoised with `centre` (frame `frame`).
void require_compatible(const FrameInputs& centre, const FrameInputs& neighbour, int frame, int other)
{
    const std::string context = format("--temporal : neighbour frame {} ({})", other, neighbour.path);
    const OIIO::ROI c = centre.beauty.roi(), n = neighbour.beauty.roi();
    const OIIO::ROI cf = centre.input->roi_full(), nf = neighbour.input->roi_full();
    if (cf != nf)
        throw RunError(format("{} : display window {} differs from frame {}'s {}: every frame of a shot needs "
                              "the same resolution", context, window_text(nf), frame, window_text(cf)));
    if (c != n)
        throw RunError(format("{} : data window {} differs from frame {}'s {}", context, window_text(n), frame,
                              window_text(c)));
    if (c.nchannels() != n.nchannels())
        throw RunError(format("{} : {} beauty channels, frame {} has {}", context, n.nchannels(), frame,
                              c.nchannels()));
    if (role_list(centre.guides) != role_list(neighbour.guides))
        throw RunError(format("{} : has the guides {}, frame {} has {}", context, role_list(neighbour.guides),
                              frame, role_list(centre.guides)));
}

}  // namespace

FrameWindow::Held& FrameWindow::get(int frame)
{
    auto found = held_.find(frame);
    if (found == held_.end())
        found = held_.emplace(frame, Held{ read_frame_inputs(reading_, frame, stats_),
                                           std::make_unique<mcdenoise::PreparedFrame>(),
                                           std::make_unique<mcdenoise::NetworkFrame>() })
                    .first;
    return found->second;
}

const FrameInputs& FrameWindow::centre(int frame)
{
    for (auto it = held_.begin(); it != held_.end();)
        it = std::abs(it->first - frame) > reading_.temporal ? held_.erase(it) : std::next(it);
    return *get(frame).inputs;
}

WindowFrame FrameWindow::centre_frame(int frame)
{
    Held& held = get(frame);
    return WindowFrame{ 0, &held.inputs->beauty, &held.inputs->guides, held.prepared.get(), held.network.get() };
}

std::vector<WindowFrame> FrameWindow::neighbours(int frame)
{
    const FrameInputs& centre_inputs = *get(frame).inputs;
    std::vector<WindowFrame> found;
    for (int offset = -reading_.temporal; offset <= reading_.temporal; ++offset) {
        const int other = frame + offset;
        if (offset == 0)
            continue;
        const std::string path = path_for_frame(reading_.input, other);
        if (!held_.count(other) && !OIIO::Filesystem::exists(path)) {
            std::fprintf(stderr, "mcdtool WARNING: frame %d: --temporal : neighbour frame %d (%s) does not exist: "
                         "left out\n", frame, other, path.c_str());
            continue;
        }
        Held& held = [&]() -> Held& {
            try {
                return get(other);
            } catch (const RunError& error) {
                throw RunError(format("--temporal : neighbour frame {}: {}", other, error.what()));
            }
        }();
        const FrameInputs& inputs = *held.inputs;
        require_compatible(centre_inputs, inputs, frame, other);
        found.push_back(WindowFrame{ offset, &inputs.beauty, &inputs.guides, held.prepared.get(), held.network.get() });
    }
    return found;
}

}  // namespace mcdtool
