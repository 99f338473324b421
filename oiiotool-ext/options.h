// options.h: what a parsed mcdtool command line holds, and the table of
// global options (like the command table, --help is generated from it).
#pragma once

#include "commands.h"
#include "roles.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace mcdtool {

/// Most frames --temporal takes on each side of a frame (2N+1 frames are
/// held in memory; Cycles' animation denoiser took at most 7).
constexpr int max_temporal_radius = 8;

/// One thing done, left to right, to the current image: a command or -o.
struct Step {
    const Command* command = nullptr;  ///< nullptr for an output (-o)
    std::vector<std::string> values;   ///< the command's parameters
    ModifierValues modifiers;          ///< its `:KEY=VALUE` modifiers
    std::string output;                ///< the -o path (may hold a frame pattern)
};

/// `--aov ROLE=FILE[:CHANNELS]` as typed.
struct AovRequest {
    Role role;
    std::string file;      ///< may hold a frame pattern
    std::string channels;  ///< comma list or layer prefix; empty: all, in order
    std::string typed;     ///< the argument as typed, for messages
};

/// How --preview turns scene-linear pixels into display values.
struct DisplayChoice {
    std::string ocio_config;  ///< --ocio-config (empty: $OCIO or sRGB)
    std::string display;      ///< --display (empty: config default)
    std::string view;         ///< --view (empty: display default)

    /// True if any of the three was given.
    bool given() const { return !ocio_config.empty() || !display.empty() || !view.empty(); }
};

/// What -d and --compression change of the input file's spec.
struct OutputFormat {
    std::string data_format;  ///< -d (empty: the input's)
    std::string compression;  ///< --compression (empty: the input's)
};

/// What the program was asked to do.
enum class Mode { run, help, help_markdown, version };

/// A parsed command line.
struct Options {
    Mode mode = Mode::run;
    std::string input;               ///< may hold a frame pattern
    std::vector<Step> steps;
    std::vector<AovRequest> aovs;
    std::string beauty_channels;     ///< --beauty (empty: discover)
    std::string light_passes;        ///< --aovs auto|LIST (empty: none)
    std::string frames;              ///< --frames (empty: a single image)
    int temporal = 0;                ///< --temporal: frames before and after each frame --denoise uses
    OutputFormat format;             ///< -d, --compression
    std::string compare;             ///< --compare REF
    std::string preview;             ///< --preview FILE.png
    DisplayChoice display;           ///< --ocio-config, --display, --view
    int threads = 0;
    uint64_t memory_limit_mb = 0;    ///< --memory-limit (0: physical memory)
    bool verbose = false;
    bool runstats = false;
    bool force = false;
    bool skip_existing = false;
};

/// Sets the fields of Options from an option's arguments (already counted).
using OptionFn = void (*)(Options&, const std::vector<std::string>&);

/// One global option (position independent, except -o which is a step).
struct OptionSpec {
    const char* name;                  ///< without dashes: "o", "frames"
    std::vector<const char*> params;   ///< argument names for usage
    const char* group;                 ///< help section
    const char* help;
    OptionFn apply;
};

/// Every global option, in help order.
const std::vector<OptionSpec>& option_table();

/// "-o FILE" / "--frames LIST": how an option is typed.
std::string option_usage(const OptionSpec& option);

/// "-o" or "--frames": a name with its dashes.
std::string dashed(std::string_view name);

/// Parses argv into Options; throws UsageError naming the culprit.
Options parse_command_line(const std::vector<std::string>& args);

/// The candidate nearest to `typed` by edit distance (Levenshtein with
/// adjacent transpositions); the first of equals; empty if there is none.
std::string nearest(std::string_view typed, const std::vector<std::string>& candidates);

}  // namespace mcdtool
