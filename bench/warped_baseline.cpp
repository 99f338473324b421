// warped_baseline.cpp: the naive cross-frame baseline of docs/temporal.md
// on any renderer's files, for bench/render_table: the per-frame `denoise`
// results of a frame and its neighbours averaged, each neighbour carried
// into the frame by the motion guide and kept where the depths agree
// (mcdenoise's warped_average). The frames' guides are found as mcdtool
// finds them (testrender's motion.*, Cycles' Vector, depth), so the
// baseline sees what --temporal sees.
//
// Usage: warped_baseline OUT.exr FRAME RESULT [NEIGHBOUR RESULT OFFSET]...
//   FRAME, NEIGHBOUR  input files (the renders)
//   RESULT            the file's `mcdtool --denoise` output
//   OFFSET            the neighbour's frame number minus FRAME's
// Writes the baseline's beauty (float RGB) to OUT.exr.
#include "error.h"
#include "frame_inputs.h"
#include "support/warped_average.h"

#include <OpenImageIO/imagebufalgo.h>

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace {

using mcdtool::FrameInputs;
using OIIO::ImageBuf;

/// A render's beauty and guides (motion and depth among them) as mcdtool
/// reads them.
std::unique_ptr<FrameInputs> read_frame(const std::string& path, mcdtool::RunStats& stats)
{
    mcdtool::FrameReading reading;
    reading.input = path;
    reading.roles = { mcdtool::Role::motion, mcdtool::Role::depth };
    return mcdtool::read_frame_inputs(reading, std::nullopt, stats);
}

/// The beauty channels of a result file, found as in its input.
ImageBuf read_result(const std::string& path, const FrameInputs& like)
{
    ImageBuf file(path);
    if (!file.read(0, 0, true, OIIO::TypeDesc::FLOAT))
        throw mcdtool::RunError(path + " : " + file.geterror());
    const mcdtool::Discovery found = mcdtool::discover_channels(file.spec(), "", path);
    if (found.beauty.size() != like.found.beauty.size())
        throw mcdtool::RunError(path + " : its beauty does not match its input's");
    return mcdtool::extract_channels(file, found.beauty);
}

int run(int argc, char** argv)
{
    mcdtool::RunStats stats;
    const auto centre = read_frame(argv[2], stats);
    const ImageBuf centre_result = read_result(argv[3], *centre);
    std::vector<std::unique_ptr<FrameInputs>> frames;
    std::vector<ImageBuf> results;
    std::vector<int> offsets;
    for (int i = 4; i + 2 < argc; i += 3) {
        frames.push_back(read_frame(argv[i], stats));
        results.push_back(read_result(argv[i + 1], *frames.back()));
        offsets.push_back(std::stoi(argv[i + 2]));
    }
    const auto input = [](const FrameInputs& f) {
        return mcdenoise::FrameInput { &f.beauty, mcdtool::library_guides(f.guides) };
    };
    std::vector<mcdenoise::FrameInput> neighbours;
    std::vector<const ImageBuf*> neighbour_results;
    for (size_t k = 0; k < frames.size(); ++k) {
        neighbours.push_back(input(*frames[k]));
        neighbour_results.push_back(&results[k]);
    }
    ImageBuf out;
    if (!mcdenoise::warped_average(out, input(*centre), centre_result, neighbours, neighbour_results, offsets)
        || !out.write(argv[1])) {
        std::fprintf(stderr, "warped_baseline: %s\n", out.geterror().c_str());
        return 1;
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv)
{
    if (argc < 4 || (argc - 4) % 3 != 0) {
        std::fprintf(stderr, "usage: warped_baseline OUT.exr FRAME RESULT [NEIGHBOUR RESULT OFFSET]...\n");
        return 2;
    }
    try {
        return run(argc, argv);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "warped_baseline: %s\n", e.what());
        return 1;
    }
}
