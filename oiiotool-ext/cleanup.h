// cleanup.h: what happens to mcdtool's temp files when the process is
// stopped. SIGINT, SIGTERM and SIGHUP remove every temp file still being
// written (a fixed table of paths the handler reads without allocating),
// then take their default action; SIGXFSZ is ignored so that a file size
// limit (ulimit -f) surfaces as a write error naming the file. A SIGKILL
// can leave a temp file behind, always under its hidden temp name
// (".NAME.mcdtool-PID-N.EXT"), never under the final name.
#pragma once

#include <string>

namespace mcdtool {

/// Installs the handlers above. Call once, from main().
void install_interrupt_cleanup();

/// Marks `path` for removal if the process is interrupted; returns its slot,
/// or -1 when every slot is taken (the file is then not removed on a signal).
int track_temp_file(const std::string& path);

/// Forgets `slot` (from track_temp_file): its file was renamed or removed.
void untrack_temp_file(int slot);

}  // namespace mcdtool
