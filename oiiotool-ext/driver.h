// driver.h: mcdtool as a function: the whole program (parse, help, run every
// frame, report) behind one call, so main() and the in-process fuzz target
// share it.
#pragma once

#include <string>
#include <vector>

namespace mcdtool {

/// Runs mcdtool on `args` (argv without the program name) and returns the
/// exit status: 0 on success, 1 when a frame failed to read, filter or
/// write, 2 for a malformed command line. Errors go to stderr as one line
/// each; nothing throws.
int run_mcdtool(const std::vector<std::string>& args);

}  // namespace mcdtool
