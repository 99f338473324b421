// driver_fuzz.cpp: libFuzzer target for mcdtool's argument parsing and
// command execution. The input is a command line, one argument per line;
// it runs in-process (run_mcdtool) in a scratch directory holding small
// renders laid out afresh for every input: testrender names with overscan,
// a Blender Cycles multilayer EXR, separate guide files with other data
// windows, a two-frame sequence, a PNG. Arguments holding '/' are dropped,
// so every path stays inside the scratch directory. Invariants: the exit
// status is 0, 1 or 2, no input file changes unless --force is given, and
// no temp file is left behind.
#include "driver.h"
#include "fuzz_dir.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

namespace {

using OIIO::ImageBuf;
using OIIO::ImageSpec;
using OIIO::TypeDesc;

/// Longest command line and argument tried (longer inputs add nothing).
constexpr size_t max_args = 32;
constexpr size_t max_arg_length = 128;

/// Writes an image of `names` channels with values from `value(x, y, c)`.
template<class ValueFn>
void write_image(const std::string& path, int width, int height, int x0, int y0,
                 const std::vector<std::string>& names, TypeDesc format, const char* compression,
                 ValueFn value)
{
    ImageSpec spec(width, height, int(names.size()), format);
    spec.x = x0;
    spec.y = y0;
    spec.full_x = 0;
    spec.full_y = 0;
    spec.full_width = 10;
    spec.full_height = 8;
    spec.channelnames = names;
    spec.attribute("compression", compression);
    ImageBuf image(spec);
    std::vector<float> pixels;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            for (size_t c = 0; c < names.size(); ++c)
                pixels.push_back(value(x, y, int(c)));
    image.set_pixels(image.roi(), TypeDesc::FLOAT, pixels.data());
    image.write(path);
}

/// The renders every input starts from, registered in `dir`.
void make_scene(mcdfuzz::FuzzDir& dir)
{
    std::mt19937 rng(1);
    std::uniform_real_distribution<float> noise(0.0f, 1.0f);
    auto render_value = [&](int x, int, int c) -> float {
        switch (c) {
        case 4: return float(x / 4);                  // id
        case 5: return x > 6 ? 1.0f : -1.0f;          // reflid
        case 6: case 7: return 0.0f;                  // N.X, N.Y
        case 8: return 1.0f;                          // N.Z
        case 9: return x > 8 ? 1e10f : 2.0f + x;      // Z
        default: return noise(rng) * (x == 3 ? 1e4f : 1.0f);
        }
    };
    const std::vector<std::string> render = { "R", "G", "B", "A", "id", "reflid", "N.X", "N.Y", "N.Z", "Z" };
    write_image("render.exr", 12, 10, -1, -1, render, TypeDesc::HALF, "piz", render_value);
    write_image("shot.0001.exr", 10, 8, 0, 0, render, TypeDesc::HALF, "zip", render_value);
    write_image("shot.0002.exr", 10, 8, 0, 0, render, TypeDesc::FLOAT, "none", render_value);
    const std::vector<std::string> cycles = {
        "View Layer.Combined.R", "View Layer.Combined.G", "View Layer.Combined.B", "View Layer.Combined.A",
        "View Layer.IndexOB.X",  "View Layer.Depth.Z",    "View Layer.Normal.X",   "View Layer.Normal.Y",
        "View Layer.Normal.Z",   "View Layer.Denoising Albedo.R", "View Layer.Denoising Albedo.G",
        "View Layer.Denoising Albedo.B"
    };
    write_image("cycles.exr", 10, 8, 0, 0, cycles, TypeDesc::FLOAT, "zip", [&](int x, int y, int c) -> float {
        if (c == 4)
            return float((x + y) % 3);
        if (c == 5)
            return y < 2 ? 1e10f : 3.0f + y;
        if (c == 0 && x == y)
            return std::nanf("");
        return noise(rng);
    });
    write_image("ids.exr", 14, 12, -2, -2, { "Y" }, TypeDesc::FLOAT, "zip",
                [](int x, int, int) { return float(x / 3); });
    write_image("small_ids.exr", 5, 4, 2, 2, { "Y" }, TypeDesc::FLOAT, "zip",
                [](int x, int, int) { return float(x); });
    write_image("normal.exr", 10, 8, 0, 0, { "R", "G", "B" }, TypeDesc::HALF, "zip",
                [](int x, int, int c) { return c == 2 ? 1.0f : 0.1f * x; });
    write_image("depth.exr", 10, 8, 0, 0, { "Y" }, TypeDesc::FLOAT, "zip",
                [](int x, int y, int) { return x == y ? INFINITY : 1.0f + x; });
    write_image("ref.exr", 10, 8, 0, 0, { "R", "G", "B" }, TypeDesc::HALF, "zip",
                [](int, int, int) { return 0.5f; });
    write_image("small.png", 10, 8, 0, 0, { "R", "G", "B" }, TypeDesc::UINT8, "none",
                [&](int, int, int) { return noise(rng); });
    for (const char* name : { "render.exr", "shot.0001.exr", "shot.0002.exr", "cycles.exr", "ids.exr",
                              "small_ids.exr", "normal.exr", "depth.exr", "ref.exr", "small.png" })
        dir.add(name, mcdfuzz::file_bytes(name));
}

mcdfuzz::FuzzDir* scratch = nullptr;

/// The registered files whose bytes must not change without --force.
const char* const inputs[] = { "render.exr", "cycles.exr", "ids.exr", "ref.exr" };

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
    unsetenv("OCIO");
    static mcdfuzz::FuzzDir dir("driver");
    scratch = &dir;
    dir.reset();
    make_scene(dir);
    dir.leave();
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    std::vector<std::string> args(1);
    for (size_t i = 0; i < size; ++i) {
        char ch = char(data[i]);
        if (ch == '\n') {
            args.emplace_back();
            continue;
        }
        if (ch == '/' || ch == '\0' || args.back().size() >= max_arg_length || args.size() > max_args)
            return 0;
        args.back() += ch;
    }
    if (!args.empty() && args.back().empty())
        args.pop_back();
    scratch->reset();
    std::vector<std::string> before;
    for (const char* name : inputs)
        before.push_back(mcdfuzz::file_bytes(name));

    const int status = mcdtool::run_mcdtool(args);
    mcdfuzz::require(status == 0 || status == 1 || status == 2, "exit status is 0, 1 or 2");
    if (std::find(args.begin(), args.end(), "--force") == args.end())
        for (size_t i = 0; i < before.size(); ++i)
            mcdfuzz::require(mcdfuzz::file_bytes(inputs[i]) == before[i], "an input file was changed");
    // A temp file is ".NAME.mcdtool-PID-N.EXT" (output.cpp); a file the
    // command line itself names (an output called "x.mcdtool-t.exr") is not.
    for (const auto& entry : std::filesystem::directory_iterator(scratch->path())) {
        const std::string name = entry.path().filename().string();
        const bool named       = std::find(args.begin(), args.end(), name) != args.end();
        mcdfuzz::require(named || name.find(".mcdtool-") == std::string::npos, "a temp file was left behind");
    }
    scratch->leave();
    return 0;
}
