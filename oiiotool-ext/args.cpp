// args.cpp: the global option table and the left-to-right command-line
// parser (an input, then commands and options, -o writes), with edit-
// distance suggestions for anything it does not know.
#include "error.h"
#include "frames.h"
#include "options.h"

#include <OpenImageIO/strutil.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace mcdtool {

using OIIO::Strutil::fmt::format;

namespace {

/// Pixel types accepted by -d.
const std::vector<std::string> data_formats = { "half", "float", "uint8", "uint16", "uint32" };

/// OpenEXR compression names accepted by --compression (":LEVEL" may follow).
const std::vector<std::string> compressions = { "none",  "rle",  "zips", "zip",  "piz",
                                                "pxr24", "b44",  "b44a", "dwaa", "dwab" };

/// Throws a UsageError unless `value` is one of `allowed`.
void require_one_of(std::string_view option, const std::string& value,
                    const std::vector<std::string>& allowed)
{
    if (std::find(allowed.begin(), allowed.end(), value) != allowed.end())
        return;
    throw UsageError(format("{} : unknown value '{}' (one of: {}; did you mean '{}'?)",
                            option, value, OIIO::Strutil::join(allowed, ", "),
                            nearest(value, allowed)));
}

/// True if `text` is a whole (optionally negative) decimal integer.
bool is_integer(const std::string& text)
{
    size_t start = (!text.empty() && (text[0] == '-' || text[0] == '+')) ? 1 : 0;
    return text.size() > start
           && std::all_of(text.begin() + start, text.end(), [](char ch) { return ch >= '0' && ch <= '9'; })
           && text.size() - start <= 9;
}

/// True if `text` is a finite decimal number.
bool is_number(const std::string& text)
{
    char* end = nullptr;
    double value = std::strtod(text.c_str(), &end);
    return !text.empty() && end == text.c_str() + text.size() && std::isfinite(value);
}

/// True if `arg` is a command or option as typed ("--median", "-o").
bool is_known_name(const std::string& arg)
{
    if (arg.size() < 2 || arg[0] != '-')
        return false;
    std::string name = arg.substr(arg[1] == '-' ? 2 : 1);
    if (find_command(name.substr(0, name.find(':'))))
        return true;
    for (const OptionSpec& option : option_table())
        if (name == option.name)
            return true;
    return false;
}

/// Parses `:KEY=VALUE[:KEY=VALUE...]` after `command`'s name (`typed`,
/// empty or starting with ':'), checking each key and value against the
/// command's row.
ModifierValues parse_modifiers(const Command& command, const std::string& arg, const std::string& typed)
{
    ModifierValues values;
    if (typed.empty())
        return values;
    for (const std::string& item : OIIO::Strutil::splits(typed.substr(1), ":")) {
        const size_t equals = item.find('=');
        const std::string key = item.substr(0, equals);
        const Modifier* modifier = nullptr;
        std::vector<std::string> keys;
        for (const Modifier& m : command.modifiers) {
            keys.push_back(m.key);
            if (key == m.key)
                modifier = &m;
        }
        if (!modifier)
            throw UsageError(format("{} : unknown modifier '{}' ({})", arg, key,
                                    keys.empty() ? std::string("--") + command.name + " takes none"
                                                 : "it takes " + OIIO::Strutil::join(keys, ", ")));
        const std::string value = equals == std::string::npos ? "" : item.substr(equals + 1);
        std::vector<std::string> allowed(modifier->values.begin(), modifier->values.end());
        if (std::find(allowed.begin(), allowed.end(), value) == allowed.end())
            throw UsageError(format("{} : {} must be one of {}, got '{}'", arg, key,
                                    OIIO::Strutil::join(allowed, ", "), value));
        values[key] = value;
    }
    return values;
}

/// Parses "ROLE=FILE[:CHANNELS]".
AovRequest parse_aov(const std::string& typed)
{
    size_t eq = typed.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == typed.size())
        throw UsageError(format("--aov : expected ROLE=FILE[:CHANNELS], got '{}'", typed));
    std::string role_name = typed.substr(0, eq);
    const RoleInfo* info = find_role(role_name);
    if (!info) {
        std::vector<std::string> names;
        for (const RoleInfo& r : role_table())
            names.push_back(r.name);
        throw UsageError(format("--aov : unknown role '{}' (did you mean '{}'? roles: {})", role_name,
                                nearest(role_name, names), OIIO::Strutil::join(names, ", ")));
    }
    AovRequest aov{ info->role, typed.substr(eq + 1), "", typed };
    size_t colon = aov.file.rfind(':');
    if (colon != std::string::npos && aov.file.find('/', colon) == std::string::npos) {
        aov.channels = aov.file.substr(colon + 1);
        aov.file = aov.file.substr(0, colon);
    }
    if (aov.file.empty())
        throw UsageError(format("--aov : no file in '{}'", typed));
    return aov;
}

/// Throws a UsageError unless `value` (already known to be a number) is in
/// `param`'s range, and odd if it must be.
void require_in_range(const std::string& arg, const Param& param, const std::string& value)
{
    double number = std::strtod(value.c_str(), nullptr);
    if (number < param.min || number > param.max)
        throw UsageError(format("{} : {} out of range ({}), got {}", arg, param.name, param.help, value));
    if (param.odd && std::fmod(number, 2.0) == 0.0)
        throw UsageError(format("{} : {} must be odd ({}), got {}", arg, param.name, param.help, value));
}

/// Converts a --threads argument.
int parse_threads(const std::string& text)
{
    if (!is_integer(text) || OIIO::Strutil::stoi(text) < 0)
        throw UsageError(format("--threads : expected a count >= 0, got '{}'", text));
    return OIIO::Strutil::stoi(text);
}

/// Converts a --temporal argument (0..mcdenoise::max_temporal_radius).
int parse_temporal(const std::string& text)
{
    if (!is_integer(text) || OIIO::Strutil::stoi(text) < 0 || OIIO::Strutil::stoi(text) > max_temporal_radius)
        throw UsageError(format("--temporal : expected a frame count 0..{}, got '{}'", max_temporal_radius, text));
    return OIIO::Strutil::stoi(text);
}

/// Converts a --memory-limit argument (MiB, >= 1).
uint64_t parse_memory_limit(const std::string& text)
{
    if (!is_integer(text) || OIIO::Strutil::stoi(text) < 1)
        throw UsageError(format("--memory-limit : expected a whole number of MiB >= 1, got '{}'", text));
    return uint64_t(OIIO::Strutil::stoi(text));
}

}  // namespace

const std::vector<OptionSpec>& option_table()
{
    static const std::vector<OptionSpec> table = {
        { "o", { "FILE" }, "Output",
          "Write the current image: every input channel and the metadata kept, the beauty "
          "channels replaced, in the input's pixel type and compression (a format that cannot keep every channel "
          "by name, like PNG or TIFF, gets the beauty only); the folder is made if missing. Atomic (temp file + "
          "rename); a replaced file keeps its mode, a write-protected one needs --force.",
          [](Options& o, const std::vector<std::string>& a) { o.steps.push_back(Step{ nullptr, {}, {}, a[0] }); } },
        { "d", { "TYPE" }, "Output", "Pixel type of the outputs: half, float, uint8, uint16 or uint32.",
          [](Options& o, const std::vector<std::string>& a) {
              require_one_of("-d", a[0], data_formats);
              o.format.data_format = a[0];
          } },
        { "compression", { "NAME" }, "Output",
          "Compression of the outputs (none, rle, zips, zip, piz, pxr24, b44, b44a, dwaa, dwab; "
          "NAME:LEVEL allowed).",
          [](Options& o, const std::vector<std::string>& a) {
              require_one_of("--compression", a[0].substr(0, a[0].find(':')), compressions);
              o.format.compression = a[0];
          } },
        { "force", {}, "Output", "Allow an output to replace an input file or a write-protected file.",
          [](Options& o, const std::vector<std::string>&) { o.force = true; } },
        { "aov", { "ROLE=FILE[:CHANNELS]" }, "Guides",
          "Take a guide from FILE: CHANNELS is a comma list or a layer prefix (render.exr:N selects "
          "N.X,N.Y,N.Z); without it, the file's channels in order. Overrides discovery.",
          [](Options& o, const std::vector<std::string>& a) { o.aovs.push_back(parse_aov(a[0])); } },
        { "aovs", { "auto|LIST" }, "Guides",
          "With --denoise: denoise these light passes with the beauty's own weights, so passes that add up "
          "to the beauty still do (auto: every known light pass beside the beauty, see \"Light passes\"; "
          "LIST: pass names, comma separated). A Cycles-style beauty is rebuilt from its denoised passes.",
          [](Options& o, const std::vector<std::string>& a) { o.light_passes = a[0]; } },
        { "beauty", { "CHANNELS" }, "Guides",
          "The channels to filter (comma list or layer prefix) instead of the discovered beauty.",
          [](Options& o, const std::vector<std::string>& a) { o.beauty_channels = a[0]; } },
        { "frames", { "LIST" }, "Sequences",
          "Frames for a pattern (# or #### = 4 digits, @ = 1 digit each, %04d): 1-48, 1-10x2, 1,3,5.",
          [](Options& o, const std::vector<std::string>& a) {
              parse_frame_list(a[0]);
              o.frames = a[0];
          } },
        { "temporal", { "N" }, "Sequences",
          "With --frames and --denoise: denoise each frame with the N frames before and after it (0: each "
          "frame alone). Neighbours are read from the files on disk, also outside --frames, so a sequence "
          "split across runs gives the same files; a missing neighbour is warned about and left out.",
          [](Options& o, const std::vector<std::string>& a) { o.temporal = parse_temporal(a[0]); } },
        { "skip-existing", {}, "Sequences", "Skip frames whose outputs all exist already.",
          [](Options& o, const std::vector<std::string>&) { o.skip_existing = true; } },
        { "compare", { "REF" }, "Diagnostics",
          "Print relMSE, PSNR and SSIM of the result against REF's beauty (a pattern for sequences). PSNR is "
          "relative to a peak of 1 on values clamped to [0, 1] (the displayable range of a linear render, as for "
          "SSIM), so it stays positive on HDR renders.",
          [](Options& o, const std::vector<std::string>& a) { o.compare = a[0]; } },
        { "preview", { "FILE" }, "Diagnostics",
          "Write a display-referred side-by-side image: input | result (| reference with --compare).",
          [](Options& o, const std::vector<std::string>& a) { o.preview = a[0]; } },
        { "ocio-config", { "FILE" }, "Diagnostics",
          "OpenColorIO config for --preview (default: $OCIO, else a plain sRGB transform).",
          [](Options& o, const std::vector<std::string>& a) { o.display.ocio_config = a[0]; } },
        { "display", { "NAME" }, "Diagnostics", "OCIO display for --preview (default: the config's).",
          [](Options& o, const std::vector<std::string>& a) { o.display.display = a[0]; } },
        { "view", { "NAME" }, "Diagnostics", "OCIO view for --preview (default: the display's).",
          [](Options& o, const std::vector<std::string>& a) { o.display.view = a[0]; } },
        { "threads", { "N" }, "Diagnostics", "Threads per filter (0: all cores).",
          [](Options& o, const std::vector<std::string>& a) { o.threads = parse_threads(a[0]); } },
        { "memory-limit", { "MB" }, "Diagnostics",
          "Refuse, with an error naming the file, an image or a frame whose pixels need more than MB MiB "
          "(default: the machine's physical memory). Checked from the file headers before allocating.",
          [](Options& o, const std::vector<std::string>& a) { o.memory_limit_mb = parse_memory_limit(a[0]); } },
        { "runstats", {}, "Diagnostics",
          "Print time per command (the total, and over a sequence its fastest call), I/O time and peak "
          "memory at the end.",
          [](Options& o, const std::vector<std::string>&) { o.runstats = true; } },
        { "v", {}, "Diagnostics", "Verbose: the channels used for each role, and each step.",
          [](Options& o, const std::vector<std::string>&) { o.verbose = true; } },
        { "help", {}, "Help", "Print this help.",
          [](Options& o, const std::vector<std::string>&) { o.mode = Mode::help; } },
        { "help-markdown", {}, "Help", "Print the reference (docs/mcdtool.md) as Markdown.",
          [](Options& o, const std::vector<std::string>&) { o.mode = Mode::help_markdown; } },
        { "version", {}, "Help", "Print the version.",
          [](Options& o, const std::vector<std::string>&) { o.mode = Mode::version; } },
    };
    return table;
}

std::string dashed(std::string_view name)
{
    return (name.size() == 1 ? "-" : "--") + std::string(name);
}

std::string option_usage(const OptionSpec& option)
{
    std::string usage = dashed(option.name);
    for (const char* param : option.params)
        usage += std::string(" ") + param;
    return usage;
}

std::string nearest(std::string_view typed, const std::vector<std::string>& candidates)
{
    std::string best;
    size_t best_distance = std::string::npos;
    for (const std::string& candidate : candidates) {
        // Optimal string alignment distance: Levenshtein plus adjacent
        // transpositions, so "--medain" is one step from "--median".
        size_t rows = typed.size() + 1;
        size_t cols = candidate.size() + 1;
        std::vector<size_t> d(rows * cols);
        for (size_t i = 0; i < rows; ++i)
            d[i * cols] = i;
        for (size_t j = 0; j < cols; ++j)
            d[j] = j;
        for (size_t i = 1; i < rows; ++i)
            for (size_t j = 1; j < cols; ++j) {
                size_t cost = typed[i - 1] == candidate[j - 1] ? 0 : 1;
                size_t best_here = std::min({ d[(i - 1) * cols + j] + 1, d[i * cols + j - 1] + 1,
                                              d[(i - 1) * cols + j - 1] + cost });
                if (i > 1 && j > 1 && typed[i - 1] == candidate[j - 2] && typed[i - 2] == candidate[j - 1])
                    best_here = std::min(best_here, d[(i - 2) * cols + j - 2] + 1);
                d[i * cols + j] = best_here;
            }
        size_t distance = d.back();
        if (distance < best_distance) {
            best_distance = distance;
            best = candidate;
        }
    }
    return best;
}

Options parse_command_line(const std::vector<std::string>& args)
{
    Options options;
    std::vector<std::string> known;  // names without dashes, for suggestions
    for (const Command& command : command_table())
        known.push_back(command.name);
    for (const OptionSpec& option : option_table())
        known.push_back(option.name);

    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& arg = args[i];
        if (arg.size() < 2 || arg[0] != '-') {
            if (!options.input.empty())
                throw UsageError(format("unexpected argument '{}' (the input is already '{}'; "
                                        "write outputs with -o FILE)", arg, options.input));
            options.input = arg;
            continue;
        }
        std::string name = arg.substr(arg[1] == '-' ? 2 : 1);
        const std::string typed_modifiers = name.find(':') == std::string::npos ? "" : name.substr(name.find(':'));
        name = name.substr(0, name.find(':'));
        const Command* command = find_command(name);
        const OptionSpec* option = nullptr;
        for (const OptionSpec& spec : option_table())
            if (name == spec.name)
                option = &spec;
        if (!command && !option)
            throw UsageError(format("unknown command '{}'; did you mean '{}'? (mcdtool --help lists them)",
                                    arg, dashed(nearest(name, known))));

        size_t nparams = command ? command->params.size() : option->params.size();
        std::string usage = command ? command_usage(*command) : option_usage(*option);
        std::vector<std::string> values;
        for (size_t p = 0; p < nparams; ++p) {
            size_t at = i + 1 + p;
            bool looks_like_option = at < args.size() && is_known_name(args[at]);
            if (at >= args.size() || looks_like_option)
                throw UsageError(format("{} : missing argument (usage: {}{})", arg, usage,
                                        at < args.size() ? format("; got '{}'", args[at]) : ""));
            values.push_back(args[at]);
        }
        i += nparams;
        if (option && !typed_modifiers.empty())
            throw UsageError(format("{} : options take no ':' modifiers", arg));
        if (option) {
            option->apply(options, values);
            continue;
        }
        for (size_t p = 0; p < nparams; ++p) {
            const Param& param = command->params[p];
            bool ok = param.type == ParamType::integer ? is_integer(values[p]) : is_number(values[p]);
            if (!ok)
                throw UsageError(format("{} : {} must be {}, got '{}' (usage: {})", arg, param.name,
                                        param.type == ParamType::integer ? "an integer" : "a number",
                                        values[p], usage));
            require_in_range(arg, param, values[p]);
        }
        options.steps.push_back(Step{ command, values, parse_modifiers(*command, arg, typed_modifiers), "" });
    }

    if (options.mode != Mode::run)
        return options;
    if (options.input.empty())
        throw UsageError("no input image (usage: mcdtool INPUT [commands...] -o OUTPUT; see --help)");
    bool pattern = has_frame_pattern(options.input);
    if (pattern && options.frames.empty())
        throw UsageError(format("'{}' is a frame pattern: give --frames (e.g. --frames 1-48)", options.input));
    if (!pattern && !options.frames.empty())
        throw UsageError(format("--frames given but the input '{}' has no frame pattern (#, @ or %04d)",
                                options.input));
    std::vector<std::pair<std::string, std::string>> outputs;  // (option, path)
    for (const Step& step : options.steps)
        if (!step.command)
            outputs.emplace_back("-o", step.output);
    if (!options.preview.empty())
        outputs.emplace_back("--preview", options.preview);
    for (const auto& [option, path] : outputs) {
        if (pattern && !has_frame_pattern(path))
            throw UsageError(format("{} '{}' has no frame pattern: every frame would write it (use e.g. "
                                    "'{}')", option, path, "clean.####.exr"));
        if (!pattern && has_frame_pattern(path))
            throw UsageError(format("{} '{}' has a frame pattern but the input '{}' has none", option, path,
                                    options.input));
    }
    return options;
}

}  // namespace mcdtool
