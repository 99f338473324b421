// runstats.h: what --runstats prints (time per command, I/O time, frames
// written, skipped and failed, peak memory from getrusage), the summary
// line of a sequence and the progress line on a terminal.
#pragma once

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace mcdtool {

/// Seconds since construction.
class Timer {
public:
    Timer() : start_(std::chrono::steady_clock::now()) {}
    /// Seconds elapsed.
    double seconds() const
    {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    }

private:
    std::chrono::steady_clock::time_point start_;
};

/// What happened to one frame (run_frame throws rather than return failed).
enum class FrameOutcome { written, skipped, failed };

class Progress;

/// Totals over the whole run.
class RunStats {
public:
    /// Adds one call of `command` that took `seconds`.
    void add_command(const std::string& command, double seconds);
    /// Adds reading time, of one file read.
    void add_read(double seconds)
    {
        read_seconds_ += seconds;
        ++files_read_;
    }
    /// Adds writing time (outputs and previews).
    void add_write(double seconds) { write_seconds_ += seconds; }
    /// Counts one frame done with `outcome`.
    void add_frame(FrameOutcome outcome);
    /// "48 frames: 40 written, 0 skipped, 8 failed".
    std::string frame_summary() const;
    /// Frames counted with `outcome`.
    int frames(FrameOutcome outcome) const { return counts_[int(outcome)]; }
    /// Shows the commands run from now on in `progress` (nullptr: nowhere).
    void show_progress_in(Progress* progress) { progress_ = progress; }
    /// Tells the progress line that `command` (as typed) starts.
    void begin_command(const std::string& command);
    /// Tells the progress line the fraction of the running command done.
    void command_progress(double fraction);
    /// The report, one "key value" per line, for stderr.
    std::string report() const;

private:
    struct Entry {
        std::string command;
        double seconds = 0.0;
        double fastest = 0.0;  ///< the quickest call (later frames: warm memory)
        int calls = 0;
    };
    std::vector<Entry> commands_;  ///< in order of first use
    double read_seconds_ = 0.0;
    int files_read_ = 0;  ///< image files read (each --temporal neighbour once)
    double write_seconds_ = 0.0;
    int counts_[3] = { 0, 0, 0 };  ///< by FrameOutcome
    Progress* progress_ = nullptr;
    Timer total_;
};

/// Peak resident memory of this process so far, in bytes (getrusage).
size_t peak_memory_bytes();

/// The progress line on stderr, drawn only when stderr is a terminal:
/// between frames "frame 3/48  1.2 frames/s  ETA 0:32"; while a command
/// has run for more than `slow_seconds`, "frame 3/48  --nlmeans 30  12 s",
/// redrawn in place by a background thread.
class Progress {
public:
    /// Work that takes longer than this shows the running command.
    static constexpr double slow_seconds = 2.0;

    /// A progress line for `total` frames (1: a single image, which shows
    /// only a slow command).
    explicit Progress(size_t total);
    ~Progress();
    Progress(const Progress&) = delete;
    Progress& operator=(const Progress&) = delete;
    /// Frame `frame`, the `index`-th (from 1), starts.
    void begin_frame(size_t index, int frame);
    /// `command` (as typed, with its values) starts; "" when one ends,
    /// which clears its line.
    void begin_command(const std::string& command);
    /// What the running command says of its progress ("40 % of tiles"),
    /// shown after it.
    void set_detail(const std::string& detail);
    /// Shows that `done` frames are finished; the last is `frame`.
    void update(size_t done, int frame);
    /// Ends the line so that later messages start on a fresh one.
    void finish();
    /// Clears the line before another message is printed.
    void clear();

private:
    /// The ticker thread: redraws the running command's line.
    void tick();
    /// Draws `text` over the line (the lock held).
    void draw(const std::string& text);

    size_t total_;
    bool active_;
    bool drawn_ = false;
    Timer timer_;
    std::mutex mutex_;
    std::condition_variable wake_;
    bool stop_ = false;
    std::string frame_label_;    ///< "frame 3/48  " or "" for one image
    std::string command_;        ///< the running command, "" between commands
    std::string detail_;         ///< its progress, "" when it says none
    Timer command_timer_;
    std::thread ticker_;
};

}  // namespace mcdtool
