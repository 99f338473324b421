// cpu_check.h: the load-time check that the CPU has the instruction-set
// extensions libmcdenoise was compiled for (CMake's MCD_ARCH, by default
// -march=x86-64-v3), so that on a CPU without them the library stops with a
// message naming what is missing instead of dying of SIGILL in a filter.
#pragma once

#include <cstddef>

namespace mcdenoise {

/// The extensions the library's compiler flags enable, by their
/// `__builtin_cpu_supports` names, ending with nullptr (build_isa.cpp,
/// compiled like the rest of the library).
extern const char* const build_cpu_features[];

/// Whether the CPU supports the extension `name`.
using CpuSupports = bool (*)(const char* name);

/// Writes the names of the extensions of `required` (ending with nullptr)
/// that `supports` says are missing into `out`, space-separated (`size`
/// bytes, always terminated; names that do not fit are left out), and
/// returns how many are missing.
int missing_cpu_features(const char* const* required, CpuSupports supports, char* out,
                         size_t size);

/// Whether the running CPU and OS support the extension `name`; true for a
/// name the check does not know, and on other architectures than x86.
bool running_cpu_supports(const char* name);

}  // namespace mcdenoise
