// temporal_speed.cpp: the cost of the cross-frame denoise against
// single-frame `denoise`, in the same run: frame 2 of five consecutive
// testrender frames (every AOV, the motion among them), denoised alone and
// with its neighbours +-1 and +-2, alternately, the fastest of each kept:
// in one call from the frames, and as a sequence runs it (each frame
// prepared once: one `prepare_frame` and the call of prepared frames per
// frame); and the warped-average baseline's own step (per-frame results
// given).
//
// Usage: temporal_speed FRAME0.exr ... FRAME4.exr [--threads N] [--repeats R]
#include <mcdenoise/mcdenoise.h>

#include "support/render_file.h"
#include "support/warped_average.h"

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

using OIIO::ImageBuf;
using Clock = std::chrono::steady_clock;

// The process's CPU time (user + system) in milliseconds.
double cpu_ms()
{
    rusage u {};
    getrusage(RUSAGE_SELF, &u);
    const auto ms = [](const timeval& t) { return t.tv_sec * 1e3 + t.tv_usec * 1e-3; };
    return ms(u.ru_utime) + ms(u.ru_stime);
}

// Wall and CPU milliseconds `run()` takes, each the smallest so far in
// `best`; exits on an error image.
struct Times {
    double wall = 1e30, cpu = 1e30;
};

template<class Run>
void time_ms(Times& best, Run&& run)
{
    const auto start = Clock::now();
    const double cpu0 = cpu_ms();
    const ImageBuf out = run();
    best.cpu  = std::min(best.cpu, cpu_ms() - cpu0);
    best.wall = std::min(best.wall,
                         std::chrono::duration<double, std::milli>(Clock::now() - start).count());
    if (out.has_error()) {
        std::fprintf(stderr, "temporal_speed: %s\n", out.geterror().c_str());
        std::exit(1);
    }
}

mcdenoise::FrameInput input(const testimg::Render& r)
{
    mcdenoise::FrameInput f { &r.beauty, r.guides() };
    f.guides.motion = &r.motion;
    return f;
}

}  // namespace

int main(int argc, char** argv)
{
    std::vector<std::string> files;
    int nthreads = 2, repeats = 3;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if ((a == "--threads" || a == "--repeats") && i + 1 < argc)
            (a == "--threads" ? nthreads : repeats) = std::atoi(argv[++i]);
        else
            files.push_back(a);
    }
    if (files.size() != 5 || repeats < 1) {
        std::fprintf(stderr, "usage: temporal_speed FRAME0.exr ... FRAME4.exr "
                             "[--threads N] [--repeats R]\n");
        return 2;
    }
    std::vector<testimg::Render> frames;
    for (const std::string& f : files) {
        frames.push_back(testimg::read_render(f));
        if (!frames.back().error.empty()) {
            std::fprintf(stderr, "temporal_speed: %s\n", frames.back().error.c_str());
            return 1;
        }
    }
    const mcdenoise::FrameInput centre = input(frames[2]);
    const std::vector<mcdenoise::FrameInput> neighbours { input(frames[0]), input(frames[1]),
                                                          input(frames[3]), input(frames[4]) };
    const std::vector<int> offsets { -2, -1, 1, 2 };
    std::vector<ImageBuf> results;
    for (const testimg::Render& r : frames)
        results.push_back(mcdenoise::denoise(r.beauty, r.guides(), {}, nthreads));
    const std::vector<const ImageBuf*> others { &results[0], &results[1], &results[3],
                                                &results[4] };
    std::vector<mcdenoise::PreparedFrame> prepared;
    for (const testimg::Render& r : frames)
        prepared.push_back(mcdenoise::prepare_frame(input(r), nthreads));
    const std::vector<mcdenoise::PreparedFrame> prepared_neighbours { prepared[0], prepared[1],
                                                                      prepared[3], prepared[4] };
    Times single, cross, prepare, from_prepared, average;
    for (int k = 0; k < repeats; ++k) {
        time_ms(single, [&] {
            return mcdenoise::denoise(*centre.beauty, centre.guides, {}, nthreads);
        });
        time_ms(cross, [&] {
            return mcdenoise::denoise(centre, neighbours, offsets, {}, nthreads);
        });
        time_ms(prepare, [&] {
            const mcdenoise::PreparedFrame p = mcdenoise::prepare_frame(centre, nthreads);
            ImageBuf status;
            if (!p.error.empty())
                status.errorfmt("{}", p.error);
            return status;
        });
        time_ms(from_prepared, [&] {
            return mcdenoise::denoise(prepared[2], prepared_neighbours, offsets, {}, nthreads);
        });
        time_ms(average, [&] {
            ImageBuf out;
            mcdenoise::warped_average(out, centre, results[2], neighbours, others, offsets,
                                      nthreads);
            return out;
        });
    }
    const OIIO::ROI roi = centre.beauty->roi();
    std::printf("%dx%d, %d threads, fastest of %d\n\n", roi.width(), roi.height(), nthreads,
                repeats);
    std::printf("| denoise | wall ms | x single-frame | CPU ms | x single-frame |\n"
                "|---|---|---|---|---|\n");
    const auto row = [&](const char* name, double wall, double cpu) {
        std::printf("| %s | %.0f | %.2f | %.0f | %.2f |\n", name, wall, wall / single.wall, cpu,
                    cpu / single.cpu);
    };
    row("single-frame", single.wall, single.cpu);
    row("cross-frame, N = 2, one call (5 frames prepared)", cross.wall, cross.cpu);
    row("prepare_frame (one frame)", prepare.wall, prepare.cpu);
    row("cross-frame, N = 2, of prepared frames", from_prepared.wall, from_prepared.cpu);
    row("cross-frame, N = 2, in a sequence (1 prepare_frame + the call)",
        prepare.wall + from_prepared.wall, prepare.cpu + from_prepared.cpu);
    row("baseline: 1 denoise + warped average", single.wall + average.wall,
        single.cpu + average.cpu);
    return 0;
}
