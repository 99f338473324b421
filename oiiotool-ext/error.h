// error.h: the two ways mcdtool fails, and the exit code of each.
// A UsageError (bad command line) exits 2 before any work is done; a
// RunError (unreadable file, library error, unwritable output) exits 1.
#pragma once

#include <stdexcept>
#include <string>

namespace mcdtool {

/// Exit code of a successful run.
constexpr int exit_ok = 0;
/// Exit code when any frame failed to read, filter or write.
constexpr int exit_run_error = 1;
/// Exit code for a malformed command line (unknown command, missing argument).
constexpr int exit_usage_error = 2;

/// The command line cannot be understood; nothing has been read or written.
struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// Reading, filtering or writing failed; the message names the culprit.
struct RunError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// Collapses a possibly multi-line library or OIIO message onto one line.
std::string one_line(std::string message);

}  // namespace mcdtool
