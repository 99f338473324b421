// commands.h: the command table. A command is data: its name, parameters,
// help, the guide roles it needs, an example, and a function that makes
// exactly one library call. Parsing, --help, docs/mcdtool.md and the runner
// all read this table; adding a filter is adding one row.
#pragma once

#include "light_passes.h"
#include "roles.h"

#include <OpenImageIO/imagebuf.h>

#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace mcdenoise {
struct PreparedFrame;
struct NetworkFrame;
struct Guides;
}

namespace mcdtool {

using OIIO::ImageBuf;

/// The kind of value a command parameter takes.
enum class ParamType { integer, number };

/// One positional parameter of a command, with the range the library
/// accepts, checked when the command line is parsed (before any input is
/// read).
struct Param {
    const char* name;   ///< shown in usage, e.g. "SIZE"
    ParamType type;
    const char* help;
    double min = -std::numeric_limits<double>::infinity();  ///< smallest value allowed
    double max = std::numeric_limits<double>::infinity();   ///< largest value allowed
    bool odd = false;   ///< only odd values (window sides)
};

/// A modifier a command takes after its name, `--name:KEY=VALUE`
/// (oiiotool's convention), e.g. `--denoise:quality=balanced`.
struct Modifier {
    const char* key;
    std::vector<const char*> values;  ///< the values allowed, the default first
    const char* help;
};

/// Modifiers as typed, by key.
using ModifierValues = std::map<std::string, std::string>;

/// Guide images by role, each with a note saying where it came from.
struct GuideImages {
    std::map<Role, ImageBuf> images;
    std::map<Role, std::string> sources;  ///< "render.exr: N.X,N.Y,N.Z"
};

/// The present guides of `images` in the library's form: each role whose
/// argument names a `mcdenoise::Guides` field fills it.
mcdenoise::Guides library_guides(const GuideImages& images);

/// A frame of a --temporal window as --denoise takes it: its beauty as
/// read, its guides, and where the window keeps its preparation for the
/// cross-frame denoise (temporal.h), made by the first call that needs it,
/// so a frame is prepared once for all the windows it is in.
struct WindowFrame {
    int offset;  ///< frame number minus the centre's (0: the centre)
    const ImageBuf* beauty;
    const GuideImages* guides;
    mcdenoise::PreparedFrame* prepared;
    /// Its network result (and preparation), made once likewise.
    mcdenoise::NetworkFrame* network;
};

struct Command;

/// What a command's library call receives.
struct Call {
    ImageBuf& dst;
    const ImageBuf& beauty;
    const GuideImages& guides;
    const std::vector<std::string>& values;  ///< validated against the Params
    int nthreads;
    /// With --temporal, the neighbouring frames found on disk (maybe none):
    /// --denoise then makes the cross-frame call; nullptr otherwise.
    const std::vector<WindowFrame>* neighbours = nullptr;
    /// With `neighbours`: the frame itself as its window holds it (the
    /// call's beauty is its beauty as read).
    const WindowFrame* centre = nullptr;
    /// The light passes (--aovs) a command that takes them denoises in place.
    LightLayers* layers = nullptr;
    /// The modifiers typed after the command's name (validated at parse time).
    const ModifierValues* modifiers = nullptr;
    /// --memory-limit in bytes (0: none given).
    uint64_t memory_limit = 0;
    /// -v: the command may print the times of its phases.
    bool verbose = false;

    /// Parameter `i` as an int (validated at parse time).
    int integer(size_t i) const;
    /// Parameter `i` as a float (validated at parse time).
    float number(size_t i) const;
    /// The guide for `role` (the runner checks presence before calling).
    const ImageBuf& guide(Role role) const;
    /// The guide for `role` if the input or an --aov gave one, else nullptr.
    const ImageBuf* optional_guide(Role role) const;
    /// The modifier `key` as typed, else its default (the first value the
    /// command's row allows).
    std::string modifier(const char* key) const;
    /// The command's row (for its modifiers' defaults).
    const Command* command = nullptr;
    /// Called with the fraction of the call done, for the progress line
    /// (empty: nowhere).
    std::function<void(double)> progress;
};

/// A library call with the driver's calling convention.
using CallFn = bool (*)(const Call&);

/// One row of the command table.
struct Command {
    const char* name;              ///< typed as --name (dashes, not underscores)
    const char* function;          ///< the mcdenoise function it calls
    const char* header;            ///< the library header that declares it
    std::vector<Param> params;
    std::vector<Role> roles;       ///< guides it needs, in argument order
    std::string help;              ///< one paragraph; numbers come from the library's defaults
    const char* example;           ///< a full mcdtool command line
    CallFn call;
    std::vector<Role> optional_roles = {};  ///< guides it uses when present
    bool takes_layers = false;     ///< denoises the --aovs light passes with the beauty
    std::vector<Modifier> modifiers = {};  ///< the `:KEY=VALUE` modifiers it takes
};

/// Every command, in help order.
const std::vector<Command>& command_table();

/// The command typed as `--name` (without dashes), or nullptr.
const Command* find_command(std::string_view name);

/// "--median SIZE": how a command is typed.
std::string command_usage(const Command& command);

}  // namespace mcdtool
