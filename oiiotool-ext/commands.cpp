// commands.cpp: the rows of the command table, one library call each.
// Only filters whose headers exist in imageops/include/mcdenoise/ appear.
#include "commands.h"

#include <mcdenoise/mcdenoise.h>

#include <OpenImageIO/strutil.h>

namespace mcdtool {

int Call::integer(size_t i) const { return OIIO::Strutil::stoi(values.at(i)); }

float Call::number(size_t i) const { return OIIO::Strutil::stof(values.at(i)); }

const ImageBuf& Call::guide(Role role) const { return guides.images.at(role); }

namespace {

/// The window-side parameter every window filter takes.
const Param size_param = { "SIZE", ParamType::integer, "odd window side, 1..255" };

}  // namespace

const std::vector<Command>& command_table()
{
    static const std::vector<Command> table = {
        { "mean", "simple.h", { size_param }, {},
          "Box mean of the SIZE x SIZE window (finite values only).",
          "mcdtool render.exr --mean 5 -o clean.exr",
          [](const Call& c) { return mcdenoise::mean(c.dst, c.beauty, c.integer(0), {}, c.nthreads); } },
        { "median", "simple.h", { size_param }, {},
          "Per-channel median of the SIZE x SIZE window.",
          "mcdtool render.exr --median 7 --gaussian 3 -o clean.exr",
          [](const Call& c) { return mcdenoise::median(c.dst, c.beauty, c.integer(0), {}, c.nthreads); } },
        { "gaussian", "simple.h", { size_param }, {},
          "Binomial (Pascal's triangle) weighted mean of the SIZE x SIZE window.",
          "mcdtool render.exr --gaussian 3 -o clean.exr",
          [](const Call& c) { return mcdenoise::gaussian(c.dst, c.beauty, c.integer(0), {}, c.nthreads); } },
    };
    return table;
}

const Command* find_command(std::string_view name)
{
    for (const Command& command : command_table())
        if (name == command.name)
            return &command;
    return nullptr;
}

std::string command_usage(const Command& command)
{
    std::string usage = std::string("--") + command.name;
    for (const Param& param : command.params)
        usage += std::string(" ") + param.name;
    return usage;
}

}  // namespace mcdtool
