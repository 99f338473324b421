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
    if (progress_)
        progress_->begin_command("");
    for (Entry& entry : commands_)
        if (entry.command == command) {
            entry.seconds += seconds;
            entry.fastest = std::min(entry.fastest, seconds);
            ++entry.calls;
            return;
        }
    commands_.push_back(Entry{ command, seconds, seconds, 1 });
}

void RunStats::begin_command(const std::string& command)
{
    if (progress_)
        progress_->begin_command(command);
}

void RunStats::command_progress(double fraction)
{
    if (progress_)
        progress_->set_detail(format("{:.0f} % done", 100.0 * fraction));
}

void RunStats::add_frame(FrameOutcome outcome) { ++counts_[int(outcome)]; }

std::string RunStats::frame_summary() const
{
    int written = frames(FrameOutcome::written);
    int skipped = frames(FrameOutcome::skipped);
    int failed = frames(FrameOutcome::failed);
    return format("{} frames: {} written, {} skipped, {} failed", written + skipped + failed, written, skipped,
                  failed);
}

std::string RunStats::report() const
{
    std::string text = "mcdtool runstats:\n";
    auto row = [&text](const std::string& key, const std::string& value) {
        text += format("  {:<{}} {}\n", key, runstats_key_width, value);
    };
    row("frames", format("{} ({} written, {} skipped, {} failed)", frames(FrameOutcome::written)
                          + frames(FrameOutcome::skipped) + frames(FrameOutcome::failed),
                          frames(FrameOutcome::written), frames(FrameOutcome::skipped), frames(FrameOutcome::failed)));
    row("total time", format("{:.3f} s", total_.seconds()));
    row("read time", format("{:.3f} s ({} files)", read_seconds_, files_read_));
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

/// How often the ticker thread looks at the running command.
constexpr std::chrono::milliseconds tick_interval(250);

Progress::Progress(size_t total) : total_(total), active_(total > 0 && isatty(fileno(stderr)))
{
    if (active_)
        ticker_ = std::thread([this] { tick(); });
}

Progress::~Progress()
{
    if (!ticker_.joinable())
        return;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stop_ = true;
    }
    wake_.notify_all();
    ticker_.join();
}

void Progress::begin_frame(size_t index, int frame)
{
    std::lock_guard<std::mutex> lock(mutex_);
    frame_label_ = total_ > 1 ? format("frame {} ({}/{})  ", frame, index, total_) : "";
}

void Progress::begin_command(const std::string& command)
{
    std::lock_guard<std::mutex> lock(mutex_);
    if (command.empty() && drawn_) {  // a command ended: its line goes, so messages start clean
        std::fprintf(stderr, "\r\033[K");
        drawn_ = false;
    }
    command_ = command;
    detail_.clear();
    command_timer_ = Timer();
}

void Progress::set_detail(const std::string& detail)
{
    std::lock_guard<std::mutex> lock(mutex_);
    detail_ = detail;
}

void Progress::tick()
{
    std::unique_lock<std::mutex> lock(mutex_);
    while (!wake_.wait_for(lock, tick_interval, [this] { return stop_; }))
        if (!command_.empty() && command_timer_.seconds() > slow_seconds)
            draw(format("{}{}  {:.0f} s{}", frame_label_, command_, command_timer_.seconds(),
                        detail_.empty() ? "" : "  " + detail_));
}

void Progress::draw(const std::string& text)
{
    std::fprintf(stderr, "\r\033[Kmcdtool: %s", text.c_str());
    std::fflush(stderr);
    drawn_ = true;
}

void Progress::update(size_t done, int frame)
{
    if (!active_ || total_ < 2)
        return;
    std::lock_guard<std::mutex> lock(mutex_);
    double elapsed = timer_.seconds();
    double rate = elapsed > 0.0 ? double(done) / elapsed : 0.0;
    double eta = rate > 0.0 ? double(total_ - done) / rate : 0.0;
    draw(format("frame {}  {}/{}  {:.2f} frames/s  ETA {}", frame, done, total_, rate, minutes_seconds(eta)));
}

void Progress::clear()
{
    std::lock_guard<std::mutex> lock(mutex_);
    if (active_ && drawn_) {
        std::fprintf(stderr, "\r\033[K");
        drawn_ = false;
    }
}

void Progress::finish()
{
    std::lock_guard<std::mutex> lock(mutex_);
    if (active_ && drawn_) {
        std::fprintf(stderr, "\n");
        drawn_ = false;
    }
}

}  // namespace mcdtool
