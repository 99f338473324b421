// runstats.cpp: run statistics and the terminal progress line.
#include "runstats.h"

#include <OpenImageIO/strutil.h>

#include <algorithm>
#include <cstdio>
#include <sys/resource.h>
#include <unistd.h>

namespace mcdtool {

using OIIO::Strutil::fmt::format;

namespace {

/// getrusage reports ru_maxrss in kilobytes on Linux.
constexpr size_t bytes_per_rusage_unit = 1024;
constexpr double bytes_per_mebibyte = 1024.0 * 1024.0;
constexpr int seconds_per_minute = 60;
/// Width of the key column of the --runstats report (fits every command name).
constexpr int runstats_key_width = 18;

/// "1:05" from a number of seconds.
std::string minutes_seconds(double seconds)
{
    long whole = long(seconds + 0.5);
    return format("{}:{:02d}", whole / seconds_per_minute, int(whole % seconds_per_minute));
}

}  // namespace

void RunStats::add_command(const std::string& command, double seconds)
{
    for (Entry& entry : commands_)
        if (entry.command == command) {
            entry.seconds += seconds;
            entry.fastest = std::min(entry.fastest, seconds);
            ++entry.calls;
            return;
        }
    commands_.push_back(Entry{ command, seconds, seconds, 1 });
}

std::string RunStats::report() const
{
    std::string text = "mcdtool runstats:\n";
    auto row = [&text](const std::string& key, const std::string& value) {
        text += format("  {:<{}} {}\n", key, runstats_key_width, value);
    };
    row("frames", std::to_string(frames_));
    row("total time", format("{:.3f} s", total_.seconds()));
    row("read time", format("{:.3f} s", read_seconds_));
    row("write time", format("{:.3f} s", write_seconds_));
    for (const Entry& entry : commands_)
        row(entry.command, entry.calls == 1
                               ? format("{:.3f} s (1 call)", entry.seconds)
                               : format("{:.3f} s ({} calls, fastest {:.4f} s)", entry.seconds,
                                        entry.calls, entry.fastest));
    row("peak memory", format("{:.1f} MB", double(peak_memory_bytes()) / bytes_per_mebibyte));
    return text;
}

size_t peak_memory_bytes()
{
    struct rusage usage {};
    if (getrusage(RUSAGE_SELF, &usage) != 0)
        return 0;
    return size_t(usage.ru_maxrss) * bytes_per_rusage_unit;
}

Progress::Progress(size_t total) : total_(total), active_(total > 1 && isatty(fileno(stderr))) {}

void Progress::update(size_t done, int frame)
{
    if (!active_)
        return;
    double elapsed = timer_.seconds();
    double rate = elapsed > 0.0 ? double(done) / elapsed : 0.0;
    double eta = rate > 0.0 ? double(total_ - done) / rate : 0.0;
    std::fprintf(stderr, "\r\033[Kmcdtool: frame %d  %zu/%zu  %.2f frames/s  ETA %s", frame, done, total_,
                 rate, minutes_seconds(eta).c_str());
    std::fflush(stderr);
    drawn_ = true;
}

void Progress::clear()
{
    if (active_ && drawn_) {
        std::fprintf(stderr, "\r\033[K");
        drawn_ = false;
    }
}

void Progress::finish()
{
    if (active_ && drawn_) {
        std::fprintf(stderr, "\n");
        drawn_ = false;
    }
}

}  // namespace mcdtool
