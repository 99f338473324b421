// cpu_check.cpp: stops a process that loads libmcdenoise on a CPU without
// the extensions the library was compiled for, with a message, before any
// of that code runs. This file is compiled for the baseline ISA (see
// imageops/CMakeLists.txt) and uses only C library calls, so none of its
// own code can need what it checks for.
#include "core/cpu_check.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>

#ifndef MCD_ARCH_NAME
#define MCD_ARCH_NAME "the compiler's default"
#endif

namespace mcdenoise {

int missing_cpu_features(const char* const* required, CpuSupports supports, char* out,
                         size_t size)
{
    int missing = 0;
    size_t used = 0;
    if (size > 0)
        out[0] = '\0';
    for (const char* const* name = required; *name; ++name) {
        if (supports(*name))
            continue;
        ++missing;
        const size_t length = std::strlen(*name) + (used > 0 ? 1 : 0);
        if (used + length >= size)
            continue;
        std::snprintf(out + used, size - used, "%s%s", used > 0 ? " " : "", *name);
        used += length;
    }
    return missing;
}

bool running_cpu_supports(const char* name)
{
#if defined(__x86_64__) || defined(__i386__)
    __builtin_cpu_init();  // needed before any constructor reads the CPU model
    struct Known {
        const char* name;
        bool supported;
    };
    // __builtin_cpu_supports takes only string literals; these are the
    // names GCC and clang both know (the list of build_isa.cpp).
    const Known known[] = {
        { "sse3", __builtin_cpu_supports("sse3") != 0 },
        { "ssse3", __builtin_cpu_supports("ssse3") != 0 },
        { "sse4.1", __builtin_cpu_supports("sse4.1") != 0 },
        { "sse4.2", __builtin_cpu_supports("sse4.2") != 0 },
        { "popcnt", __builtin_cpu_supports("popcnt") != 0 },
        { "avx", __builtin_cpu_supports("avx") != 0 },
        { "avx2", __builtin_cpu_supports("avx2") != 0 },
        { "fma", __builtin_cpu_supports("fma") != 0 },
        { "bmi", __builtin_cpu_supports("bmi") != 0 },
        { "bmi2", __builtin_cpu_supports("bmi2") != 0 },
        { "avx512f", __builtin_cpu_supports("avx512f") != 0 },
        { "avx512bw", __builtin_cpu_supports("avx512bw") != 0 },
        { "avx512cd", __builtin_cpu_supports("avx512cd") != 0 },
        { "avx512dq", __builtin_cpu_supports("avx512dq") != 0 },
        { "avx512vl", __builtin_cpu_supports("avx512vl") != 0 },
    };
    for (const Known& feature : known)
        if (std::strcmp(feature.name, name) == 0)
            return feature.supported;
#else
    (void)name;
#endif
    return true;
}

namespace {

/// Runs when the library is loaded, before its other constructors (priority
/// 101, the first one not reserved) and before any caller's code.
__attribute__((constructor(101))) void check_cpu()
{
    char missing[256];
    if (missing_cpu_features(build_cpu_features, running_cpu_supports, missing, sizeof missing) == 0)
        return;
    std::fprintf(stderr,
                 "libmcdenoise: this CPU lacks %s, which this build of the library needs "
                 "(compiled with -march=%s). Rebuild it for this CPU, e.g. with "
                 "cmake -DMCD_ARCH=x86-64.\n",
                 missing, MCD_ARCH_NAME);
    std::_Exit(EXIT_FAILURE);
}

}  // namespace

}  // namespace mcdenoise
