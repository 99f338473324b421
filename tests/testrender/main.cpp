// main.cpp: the testrender command line: parse arguments, render the named
// scene, write one EXR with the beauty, the AOVs and the metadata.
#include "output.h"
#include "render.h"
#include "scene.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

using namespace testrender;

constexpr int exit_usage = 2;
constexpr int max_resolution = 16384;
constexpr int max_spp = 1 << 20;
constexpr int max_threads = 1024;
constexpr int max_frame = 999999;

const char* usage_text =
    "usage: testrender --scene NAME [--res WxH] [--spp N] [--seed N] [--frame N] [--threads N]\n"
    "                  [--passes] -o FILE.exr\n"
    "       testrender --list\n"
    "  --scene NAME   built-in scene (see --list)\n"
    "  --res WxH      image size in pixels (default 256x256)\n"
    "  --spp N        samples per pixel, >= 1 (default 16)\n"
    "  --seed N       random seed, 0..2147483647 (default 1)\n"
    "  --frame N      frame of the scene's animation, 0..999999 (default 0); the noise\n"
    "                 differs per frame, frame 0 uses the seed as given\n"
    "  --threads N    worker threads, 0 = all cores (default 0); output does not depend on it\n"
    "  --passes       also write the light passes (DiffDir ... Env, Cycles' names)\n"
    "  -o FILE        output OpenEXR file\n"
    "  -q             do not print the summary line\n";

int usage_error(const std::string& message)
{
    std::fprintf(stderr, "testrender: error: %s\n%s", message.c_str(), usage_text);
    return exit_usage;
}

/// Parse a whole decimal integer in [lo, hi].
bool parse_int(const std::string& text, long long lo, long long hi, long long& value)
{
    if (text.empty())
        return false;
    char* end = nullptr;
    errno = 0;
    const long long v = std::strtoll(text.c_str(), &end, 10);
    if (errno != 0 || *end != '\0' || v < lo || v > hi)
        return false;
    value = v;
    return true;
}

bool parse_resolution(const std::string& text, int& w, int& h)
{
    const size_t x = text.find('x');
    long long a, b;
    if (x == std::string::npos || !parse_int(text.substr(0, x), 1, max_resolution, a)
        || !parse_int(text.substr(x + 1), 1, max_resolution, b))
        return false;
    w = int(a);
    h = int(b);
    return true;
}

}  // namespace

int main(int argc, char** argv)
{
    std::string scene_name, output;
    RenderSettings settings;
    bool quiet = false;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--list") {
            for (const std::string& name : scene_names()) {
                Scene s;
                make_scene(name, s);
                std::printf("%-12s %s\n", name.c_str(), s.description.c_str());
            }
            return 0;
        }
        if (arg == "-h" || arg == "--help") {
            std::fputs(usage_text, stdout);
            return 0;
        }
        if (arg == "-q") {
            quiet = true;
            continue;
        }
        if (arg == "--passes") {
            settings.passes = true;
            continue;
        }
        const bool takes_value = arg == "--scene" || arg == "--res" || arg == "--spp"
                                 || arg == "--seed" || arg == "--frame" || arg == "--threads"
                                 || arg == "-o";
        if (!takes_value)
            return usage_error("unknown argument '" + arg + "'");
        if (i + 1 >= argc)
            return usage_error(arg + " needs a value");
        const std::string value = argv[++i];
        long long n = 0;
        if (arg == "--scene") {
            scene_name = value;
        } else if (arg == "-o") {
            output = value;
        } else if (arg == "--res") {
            if (!parse_resolution(value, settings.width, settings.height))
                return usage_error("--res wants WxH with 1 <= W, H <= "
                                   + std::to_string(max_resolution) + ", got '" + value + "'");
        } else if (arg == "--spp") {
            if (!parse_int(value, 1, max_spp, n))
                return usage_error("--spp wants an integer in 1.." + std::to_string(max_spp)
                                   + ", got '" + value + "'");
            settings.spp = int(n);
        } else if (arg == "--seed") {
            if (!parse_int(value, 0, 2147483647LL, n))
                return usage_error("--seed wants an integer in 0..2147483647, got '" + value + "'");
            settings.seed = uint64_t(n);
        } else if (arg == "--frame") {
            if (!parse_int(value, 0, max_frame, n))
                return usage_error("--frame wants an integer in 0.." + std::to_string(max_frame)
                                   + ", got '" + value + "'");
            settings.frame = int(n);
        } else if (arg == "--threads") {
            if (!parse_int(value, 0, max_threads, n))
                return usage_error("--threads wants an integer in 0.." + std::to_string(max_threads)
                                   + ", got '" + value + "'");
            settings.threads = int(n);
        }
    }
    if (scene_name.empty())
        return usage_error("--scene is required (--list shows the scenes)");
    if (output.empty())
        return usage_error("-o FILE is required");
    Scene scene;
    if (!make_scene(scene_name, scene, settings.frame))
        return usage_error("unknown scene '" + scene_name + "' (--list shows the scenes)");

    const RenderBuffers buffers = render(scene, settings);
    std::string error;
    if (!write_image(to_image(buffers, scene_name, settings), output, error)) {
        std::fprintf(stderr, "testrender: error: cannot write %s: %s\n", output.c_str(),
                     error.c_str());
        return 1;
    }
    if (!quiet) {
        const double samples = double(settings.width) * settings.height * settings.spp;
        std::printf("testrender: %s %dx%d %d spp seed %llu frame %d: %.3f s, %.0f samples/s -> %s\n",
                    scene_name.c_str(), settings.width, settings.height, settings.spp,
                    (unsigned long long)settings.seed, settings.frame, buffers.seconds,
                    buffers.seconds > 0 ? samples / buffers.seconds : 0.0, output.c_str());
    }
    return 0;
}
