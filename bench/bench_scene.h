// bench_scene.h: the real testrender scene the guided-filter benchmarks run
// on, read once from the file MCD_BENCH_SCENE names (bench/speed_table
// renders it at 1920x1080).
#pragma once

#include "support/render_file.h"

namespace benchimg {

/// The scene of MCD_BENCH_SCENE, read on the first call; exits with a
/// message naming `program` if it is unset or unreadable.
const testimg::Render& bench_scene(const char* program);

}  // namespace benchimg
