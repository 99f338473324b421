// runstats.h: what --runstats prints (time per command, I/O time, peak
// memory from getrusage) and the progress line of a sequence.
#pragma once

#include <chrono>
#include <string>
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

/// Totals over the whole run.
class RunStats {
public:
    /// Adds one call of `command` that took `seconds`.
    void add_command(const std::string& command, double seconds);
    /// Adds reading time.
    void add_read(double seconds) { read_seconds_ += seconds; }
    /// Adds writing time (outputs and previews).
    void add_write(double seconds) { write_seconds_ += seconds; }
    /// Counts one frame done (written, skipped or failed).
    void add_frame() { ++frames_; }
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
    double write_seconds_ = 0.0;
    int frames_ = 0;
    Timer total_;
};

/// Peak resident memory of this process so far, in bytes (getrusage).
size_t peak_memory_bytes();

/// The "frame 3/48  1.2 frames/s  ETA 0:32" line, redrawn on stderr only
/// when stderr is a terminal.
class Progress {
public:
    /// A progress line for `total` frames (silent for a single frame).
    explicit Progress(size_t total);
    /// Shows that `done` frames are finished; the last is `frame`.
    void update(size_t done, int frame);
    /// Ends the line so that later messages start on a fresh one.
    void finish();
    /// Clears the line before another message is printed.
    void clear();

private:
    size_t total_;
    bool active_;
    bool drawn_ = false;
    Timer timer_;
};

}  // namespace mcdtool
