// help.cpp: help text and the Markdown reference, generated from the
// tables so that they cannot drift from what the parser accepts.
#include "help.h"

#include "commands.h"
#include "options.h"
#include "light_passes.h"
#include "roles.h"

#include <mcdenoise/version.h>

#include <OpenImageIO/imageio.h>
#include <OpenImageIO/strutil.h>

#include <vector>

namespace mcdtool {

using OIIO::Strutil::fmt::format;

namespace {

/// Width of the name column in the terminal help.
constexpr size_t name_column = 26;
/// Width of the terminal help.
constexpr size_t help_width = 92;

/// Help sections of the option table, in order.
const std::vector<std::string> option_groups = { "Output", "Guides", "Sequences", "Diagnostics", "Help" };

/// The one-line purpose shown at the top of both forms of help.
const char* const summary = "mcdtool: remove Monte Carlo noise from renders, oiiotool style.";

/// The exit codes and error format, shown in both forms of help.
const char* const exit_codes =
    "Errors print one line `mcdtool ERROR: <command or file> : <reason>` on stderr. Exit status: 0 "
    "success; 1 a file could not be read, filtered or written (for a sequence: any frame failed; the "
    "other frames are still written); 2 a usage error (unknown command, missing or malformed "
    "argument, a value out of its range, an unknown OCIO display or view, --beauty or --aov channels "
    "the first frame's header lacks), reported once, before any pixels are read. A failed frame leaves "
    "no output file behind; the outputs' folders are made, and --compare's reference is read, before "
    "any filtering.";

/// `text` word-wrapped to `width`, every line after the first indented by `indent`.
std::string wrap(const std::string& text, size_t indent, size_t width)
{
    std::string out;
    size_t column = indent;
    for (const std::string& word : OIIO::Strutil::splits(text, " ")) {
        if (column > indent && column + 1 + word.size() > width) {
            out += "\n" + std::string(indent, ' ');
            column = indent;
        } else if (column > indent) {
            out += " ";
            ++column;
        }
        out += word;
        column += word.size();
    }
    return out;
}

/// "  name ... help" with the help wrapped in the second column.
std::string help_row(const std::string& name, const std::string& help)
{
    std::string row = "  " + name;
    row += row.size() + 1 < name_column ? std::string(name_column - row.size(), ' ')
                                        : "\n" + std::string(name_column, ' ');
    return row + wrap(help, name_column, help_width) + "\n";
}

/// `text` safe inside a Markdown table cell ('|' escaped).
std::string cell(const std::string& text)
{
    return OIIO::Strutil::replace(text, "|", "\\|", true);
}

/// "id, normal": the roles in `roles`, or "-".
std::string role_names(const std::vector<Role>& roles)
{
    std::vector<std::string> names;
    for (Role role : roles)
        names.push_back(role_info(role).name);
    return names.empty() ? "-" : OIIO::Strutil::join(names, ", ");
}

/// "id, normal" for the roles a command needs, then "albedo, variance (each
/// if present)" for those it uses when present; "-" for none.
std::string roles_text(const Command& command)
{
    if (command.optional_roles.empty())
        return role_names(command.roles);
    const std::string optional = role_names(command.optional_roles) + " (each if present)";
    return command.roles.empty() ? optional : role_names(command.roles) + ", " + optional;
}

/// True if a command reads any guide.
bool uses_guides(const Command& command)
{
    return !command.roles.empty() || !command.optional_roles.empty();
}

/// "id, IndexOB": the pass names a role is discovered by.
std::string pass_names_text(const RoleInfo& info)
{
    std::vector<std::string> names(info.pass_names.begin(), info.pass_names.end());
    return OIIO::Strutil::join(names, ", ");
}

/// The motion role's convention, as established on Blender 3.4 renders
/// (tests/blender/test_vector_pass.py), and the other renderers' passes.
constexpr const char* motion_guide_text =
    "\n### The motion guide\n\n"
    "`motion` is Blender Cycles' `Vector` pass, 4 channels in pixels with y pointing up the image: a "
    "pixel at film position (x, y) was at (x + X, y + Y) in the previous frame and is at (x - Z, y - W) in "
    "the next (in rows counted from the top: (x + X, row - Y) and (x - Z, row + W)). So a point moving 4 "
    "pixels right and 2 up per frame has X = -4, Y = -2, Z = -4, W = -2: Cycles computes "
    "X,Y = previous - current and Z,W = current - next, in its raster space (y up), on the first hit's "
    "position. Checked on a real Cycles render by `tests/blender/test_vector_pass.py` (an orthographic "
    "shot of a cube moving by a known number of pixels; scene script `tests/blender/vector_pass_scene.py`). "
    "Cycles writes `Vector` only with motion blur off. testrender writes the same convention as "
    "`motion.X,Y,Z,W`. Only `--temporal` uses the guide; without it, each neighbour is matched by the "
    "patch search alone. Other renderers' motion passes are recognised and not used, with a warning "
    "saying why: Arnold's `motionvector` AOV is one 2D vector over the shutter interval (not to each "
    "neighbouring frame), and RenderMan's denoise channels `forward` (`motionFore`) and `backward` "
    "(`motionBack`) have no documented film scale and orientation; convert them to the convention above "
    "and give them with `--aov motion=FILE:X,Y,Z,W`.\n";

/// What --temporal does with a sequence, and --compare over one.
constexpr const char* temporal_text =
    "\n### Across frames: `--temporal N`\n\n"
    "With `--temporal N`, `--denoise` (which must then be the first command) denoises each frame with the "
    "frames up to N before and after it: the cross-frame `mcdenoise::denoise` of temporal.h, each neighbour "
    "carried by the `motion` guide when the files have one. The neighbours are the input files on disk within "
    "N frame numbers, also outside `--frames`, so a shot split across runs, farm tasks or the Python batch's "
    "chunks gives the same files as one run. Each file is read once: the frames are held in a window of up to "
    "2N+1 frames while the frames run in order (the memory of 2N+1 frames' inputs and guides; `--memory-limit` "
    "checks one frame). A neighbour missing on disk is warned about (`mcdtool WARNING: frame 1: --temporal : "
    "neighbour frame 0 (shot.0000.exr) does not exist: left out`; expected at the ends of a shot) and left out, "
    "so the frame is denoised with the neighbours that exist. A neighbour whose display or data window, beauty "
    "channel count or set of guides differs from the frame's fails that frame with an error naming both. "
    "`--temporal 0` is plain `--denoise`, byte for byte; N is at most 8.\n\n"
    "With `--compare REF` over a sequence (`--compare 'ref.####.exr'`), each frame's metrics are printed as it "
    "is done and, at the end, the figures of the whole run (frames in run order), for the input and the "
    "result: the mean of the per-frame relMSE, the temporal error (the relMSE of the frame-to-frame "
    "differences against the references' differences) and the flicker (the variance of each value across the "
    "frames over the squared mean reference + 0.01; meaningful for a static shot), as "
    "`mcdenoise::compare_sequence` (sequence_metrics.h) defines them.\n";

/// The fixed examples that are about options rather than one command.
std::vector<std::string> option_examples()
{
    return { "mcdtool 'shot/beauty.####.exr' --frames 1-48 --median 7 -o 'clean/beauty.####.exr'",
             "mcdtool render.exr --median 7 --compare reference.exr",
             "mcdtool 'shot/beauty.####.exr' --frames 1-48 --denoise --temporal 2 -o 'clean/beauty.####.exr'",
             "mcdtool render.exr --median 7 -o clean.exr --preview before_after.png",
             "mcdtool beauty.exr --aov id=ids.exr --aov normal=render.exr:N -v --median 3 -o out.exr",
             "mcdtool render.exr --median 7 -d half --compression dwaa -o clean.exr --runstats" };
}

}  // namespace

std::string version_text()
{
    return format("mcdtool {} (libmcdenoise {}, OpenImageIO {})", MCDENOISE_VERSION_STRING,
                  mcdenoise::version(), OIIO_VERSION_STRING);
}

std::string help_text()
{
    std::string text = format("{}\n\nUsage: mcdtool INPUT [COMMAND ARGS | OPTION]... -o OUTPUT\n\n", summary);
    text += "Commands run left to right on the beauty channels; each is one library call.\n";
    for (const Command& command : command_table()) {
        std::string help = command.help;
        if (uses_guides(command))
            help += " Guides: " + roles_text(command) + ".";
        text += help_row(command_usage(command), help);
        for (const Modifier& modifier : command.modifiers)
            text += help_row(format("  :{}={}", modifier.key, OIIO::Strutil::join(modifier.values, "|")),
                             format("{} (default {}).", modifier.help, modifier.values.front()));
    }
    text += "\nGuide roles (found in the input, or --aov ROLE=FILE[:CHANNELS]):\n";
    for (const RoleInfo& info : role_table())
        text += help_row(info.name, format("{}. Channels: {}. Found as: {}.", info.what, channel_count_text(info),
                                           pass_names_text(info)));
    text += "\nLight passes (--aovs auto, in the beauty's view layer):\n";
    for (const auto& [renderer, names] : known_light_passes())
        text += help_row(renderer, names + ".");
    for (const std::string& group : option_groups) {
        text += "\n" + group + ":\n";
        for (const OptionSpec& option : option_table())
            if (group == option.group)
                text += help_row(option_usage(option), option.help);
    }
    text += "\nExamples:\n";
    for (const Command& command : command_table())
        text += "  " + std::string(command.example) + "\n";
    for (const std::string& example : option_examples())
        text += "  " + example + "\n";
    text += "\n" + wrap(exit_codes, 0, help_width) + "\n";
    return text;
}

std::string help_markdown()
{
    std::string md = "# mcdtool\n\n<!-- Generated by `mcdtool --help-markdown > docs/mcdtool.md`; do not edit. -->\n\n";
    md += format("{}\n\n```\nmcdtool INPUT [COMMAND ARGS | OPTION]... -o OUTPUT\n```\n\n", summary);
    md += "It reads like oiiotool: the input, then commands applied left to right to the beauty "
          "channels, `-o` writes the current result. Each command is exactly one call into "
          "libmcdenoise (docs/filters.md has each filter's exact rule). The output keeps every input "
          "channel and the input's metadata with only the beauty channels replaced, in the input's "
          "pixel types and compression unless `-d` or `--compression` say otherwise. Files are "
          "written to a temp file beside the target and renamed into place once the whole frame "
          "succeeded; an input is never replaced unless `--force` is given.\n\n"
          "A multi-part OpenEXR (Arnold, RenderMan and Nuke put the beauty and each AOV in a part of "
          "its own) is read as one channel list, so the beauty, the guides and the light passes are "
          "found across parts: a channel of a part other than the first that has no layer gets the "
          "part's name as its layer (`R` in part `diffuse` is `diffuse.R`). An EXR output has the same "
          "parts, part names, channel names, compression and pixel types (`-d` and `--compression` apply "
          "to every part); the parts must share their data and display windows.\n\n";

    md += "## Commands\n\n| command | guides | library call | what it does |\n|---|---|---|---|\n";
    for (const Command& command : command_table())
        md += format("| `{}` | {} | `mcdenoise::{}` ({}) | {} |\n", command_usage(command), roles_text(command),
                     command.function, command.header, cell(command.help));
    for (const Command& command : command_table()) {
        md += format("\n### `--{}`\n\n{}\n\n", command.name, command.help);
        if (!command.params.empty())
            md += "| parameter | type | meaning |\n|---|---|---|\n";
        for (const Param& param : command.params)
            md += format("| `{}` | {} | {} |\n", param.name,
                         param.type == ParamType::integer ? "integer" : "number", cell(param.help));
        if (!command.modifiers.empty())
            md += format("\nModifiers (`--{}:KEY=VALUE`, several joined by `:`):\n\n"
                         "| modifier | values (default first) | meaning |\n|---|---|---|\n",
                         command.name);
        for (const Modifier& modifier : command.modifiers)
            md += format("| `{}` | {} | {} |\n", modifier.key, OIIO::Strutil::join(modifier.values, ", "),
                         cell(modifier.help));
        if (!command.roles.empty())
            md += format("\nNeeds the guides: {}.\n", role_names(command.roles));
        if (!command.optional_roles.empty())
            md += format("\nUses the guides when present: {}.\n", role_names(command.optional_roles));
        md += format("\n```\n{}\n```\n", command.example);
    }

    md += "\n## Guide roles\n\nFound automatically beside the beauty (testrender names, Blender Cycles "
          "multilayer `<ViewLayer>.<Pass>.<Channel>` names, any view-layer name, RenderMan's and "
          "Arnold's denoise AOVs) or given with "
          "`--aov ROLE=FILE[:CHANNELS]`, where CHANNELS is a comma list or a layer prefix "
          "(`render.exr:N` selects `N.X,N.Y,N.Z`) and, without it, the file's channels are taken in "
          "order. The beauty is bare `R,G,B` (or `Y`), else the first `Combined` (or RenderMan `Ci`) "
          "pass, without alpha "
          "(alpha passes through); `--beauty CHANNELS` overrides it. With no id pass, a Cryptomatte "
          "object layer's rank-0 ids (`CryptoObject00.R`, `crypto_object00.R`, or a layer whose "
          "`cryptomatte/<key>/name` metadata ends in `object`) stand in for `id`, each hash taken as "
          "the 32-bit number it codes (`--aov id=FILE:<layer>00.R` does the same); ids stored as "
          "integers (Arnold's uint `ID`) are the numbers stored. `-v` prints the channels used for "
          "each role.\n\n| role | C++ / Python argument | channels | what it is | found as |\n"
          "|---|---|---|---|---|\n";
    for (const RoleInfo& info : role_table())
        md += format("| `{}` | `{}` | {} | {} | {} |\n", info.name, info.argument, channel_count_text(info),
                     cell(info.what), pass_names_text(info));
    md += motion_guide_text;

    md += "\n## Light passes\n\n`--aovs auto` (with `--denoise`) denoises every pass of the beauty's view "
          "layer named below (`mcdenoise::denoise_layers`): with the beauty's own per-pixel weights, "
          "backed off towards the raw pass wherever those blurred it beyond the pass's own noise, "
          "then made to add up again, so passes that add up to the beauty add up to the written "
          "beauty. Only the pass's channels "
          "matching the beauty's colour (`R,G,B`) change; its alpha, the colour (filter) passes "
          "(`DiffCol`, `GlossCol`, `TransCol`, `*_albedo`), the guides and the ids are never changed. "
          "`--aovs LIST` names the passes (comma separated) instead; a name that is missing, a colour "
          "pass, a guide or the beauty is an error before any work. Cycles' `<Lobe>Dir` and `<Lobe>Ind` "
          "are irradiance (the light divided by `<Lobe>Col`): they are denoised as they are and, when "
          "the raw passes add up to the raw beauty (relMSE at most 1e-4), the written beauty is their "
          "recombination, the sum of `<Lobe>Col x (<Lobe>Dir + <Lobe>Ind)` and the other passes, so "
          "the compositor's rebuild equals it; otherwise a warning says so and the beauty is denoised "
          "on its own. docs/aovs.md has the measurements.\n\n| renderer | passes |\n|---|---|\n";
    for (const auto& [renderer, names] : known_light_passes())
        md += format("| {} | {} |\n", renderer, cell(names));
    md += "\nThe passes that add up to the beauty together (each a rebuild of its own; the passes "
          "are corrected to it wherever the raw ones add up to the raw beauty, within 1e-3 of its "
          "size):\n\n| renderer | rebuild |\n|---|---|\n";
    for (const auto& [renderer, sum] : known_rebuilds())
        md += format("| {} | {} |\n", renderer, cell(sum));

    md += "\n## Options\n";
    for (const std::string& group : option_groups) {
        md += format("\n### {}\n\n| option | meaning |\n|---|---|\n", group);
        for (const OptionSpec& option : option_table())
            if (group == option.group)
                md += format("| `{}` | {} |\n", option_usage(option), cell(option.help));
    }

    md += "\n## Sequences\n\nA frame pattern in the input, `--aov` files, `-o` and `--preview` is "
          "replaced per frame: a lone `#` is four digits (as in oiiotool), a run of N `#` or N `@` is N "
          "digits (`beauty.####.exr` -> `beauty.0007.exr`, as in Nuke), `%04d` is printf style. "
          "`--frames` takes `1-48`, `1-10x2`, `10-1`, `1,3,5` or mixtures. A progress line (frames, "
          "rate, ETA; and a command running for more than 2 s, with its time, also for a single image) "
          "is drawn on stderr when it is a terminal. A frame that fails is reported with its number and "
          "the others are still written; the exit status is then 1. A sequence ends with a summary on "
          "stderr, terminal or not: `mcdtool: 48 frames: 40 written, 0 skipped, 8 failed`.\n";
    md += temporal_text;
    md += "\n## Examples\n\n```\n";
    for (const Command& command : command_table())
        md += std::string(command.example) + "\n";
    for (const std::string& example : option_examples())
        md += example + "\n";
    md += "```\n\n## Errors and exit status\n\n" + std::string(exit_codes) + "\n";
    return md;
}

}  // namespace mcdtool
