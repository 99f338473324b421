// cleanup.cpp: the temp-file table and the signal handlers.
#include "cleanup.h"

#include <array>
#include <atomic>
#include <csignal>
#include <cstring>
#include <unistd.h>

namespace mcdtool {

namespace {

/// Temp files one run can have open at once (each -o and --preview of a
/// frame is one).
constexpr int max_tracked = 64;
/// Longest temp path tracked, with its terminating zero (Linux's PATH_MAX).
constexpr size_t max_path = 4096;

/// One tracked path; `used` is set after `path` is complete.
struct Slot {
    std::atomic<bool> used{ false };
    char path[max_path] = {};
};

std::array<Slot, max_tracked> slots;

/// The signals after which temp files are removed.
constexpr int cleanup_signals[] = { SIGINT, SIGTERM, SIGHUP };

/// Removes every tracked file, then lets `signal` do what it does by
/// default (ends the process). Uses only async-signal-safe calls.
void on_signal(int signal)
{
    for (Slot& slot : slots)
        if (slot.used.load(std::memory_order_acquire))
            unlink(slot.path);
    std::signal(signal, SIG_DFL);
    std::raise(signal);
}

}  // namespace

void install_interrupt_cleanup()
{
    for (int signal : cleanup_signals)
        std::signal(signal, on_signal);
    std::signal(SIGXFSZ, SIG_IGN);
}

int track_temp_file(const std::string& path)
{
    if (path.size() >= max_path)
        return -1;
    for (int i = 0; i < max_tracked; ++i) {
        Slot& slot = slots[size_t(i)];
        if (slot.used.load(std::memory_order_acquire))
            continue;
        std::memcpy(slot.path, path.c_str(), path.size() + 1);
        slot.used.store(true, std::memory_order_release);
        return i;
    }
    return -1;
}

void untrack_temp_file(int slot)
{
    if (slot >= 0 && slot < max_tracked)
        slots[size_t(slot)].used.store(false, std::memory_order_release);
}

}  // namespace mcdtool
