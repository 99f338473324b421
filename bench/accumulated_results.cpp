// accumulated_results.cpp: per-frame results of a shot accumulated across
// frames with the weights the network's `--temporal` accumulates the raw
// samples with (shots/shot_accumulation.h: carried by the motion guide,
// 1 where a neighbour agrees with the frame, else the temporal guide's
// weight), for the study of docs/notes/temporal.md: the network run per
// frame then filtered across frames, and the two combined. The frames'
// guides are found as mcdtool finds them, so the weights are --temporal's.
//
// Usage: accumulated_results OUT.exr FRAME RESULT [NEIGHBOUR RESULT OFFSET]...
//   FRAME, NEIGHBOUR  input files (the renders)
//   RESULT            a per-frame result of the file (an mcdtool output)
//   OFFSET            the neighbour's frame number minus FRAME's
// Writes FRAME's channels to OUT.exr (float) with its beauty replaced by
// the accumulated one, so mcdtool finds the guides in it as in FRAME.
#include "error.h"
#include "frame_inputs.h"
#include "shots/shot_accumulation.h"

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
    reading.roles = { mcdtool::Role::motion, mcdtool::Role::depth,  mcdtool::Role::normal,
                      mcdtool::Role::albedo, mcdtool::Role::variance, mcdtool::Role::half_a,
                      mcdtool::Role::half_b };
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

/// `file`'s channels `beauty` replaced by `result`'s channels, in order.
bool replace_beauty(ImageBuf& file, const ImageBuf& result, const std::vector<int>& beauty)
{
    ImageBuf floats;
    if (!OIIO::ImageBufAlgo::copy(floats, file, OIIO::TypeDesc::FLOAT))
        return false;
    for (size_t k = 0; k < beauty.size(); ++k)
        for (int y = result.ybegin(); y < result.yend(); ++y)
            for (int x = result.xbegin(); x < result.xend(); ++x)
                static_cast<float*>(floats.pixeladdr(x, y))[beauty[k]] = result.getchannel(x, y, 0, int(k));
    file = std::move(floats);
    return true;
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
    const mcdenoise::PreparedFrame c = mcdenoise::prepare_frame(input(*centre));
    std::vector<mcdenoise::PreparedFrame> prepared;
    std::vector<const mcdenoise::PreparedFrameData*> neighbours;
    std::vector<const ImageBuf*> images { &centre_result };
    for (size_t k = 0; k < frames.size(); ++k) {
        prepared.push_back(mcdenoise::prepare_frame(input(*frames[k])));
        if (!prepared.back().data)
            throw mcdtool::RunError(prepared.back().error);
        neighbours.push_back(prepared.back().data.get());
        images.push_back(&results[k]);
    }
    if (!c.data)
        throw mcdtool::RunError(c.error);
    ImageBuf out;
    ImageBuf file = *centre->input;
    if (!mcdenoise::accumulate_shot(out, *c.data, neighbours, offsets, images, centre->beauty.roi(), 0)
        || !replace_beauty(file, out, centre->found.beauty) || !file.write(argv[1], OIIO::TypeDesc::FLOAT)) {
        std::fprintf(stderr, "accumulated_results: %s %s\n", out.geterror().c_str(), file.geterror().c_str());
        return 1;
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv)
{
    if (argc < 4 || (argc - 4) % 3 != 0) {
        std::fprintf(stderr, "usage: accumulated_results OUT.exr FRAME RESULT [NEIGHBOUR RESULT OFFSET]...\n");
        return 2;
    }
    try {
        return run(argc, argv);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "accumulated_results: %s\n", e.what());
        return 1;
    }
}
