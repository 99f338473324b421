// version.h: the version of mcdenoise, as the program was compiled
// (macros) and as the library loaded at run time reports it (`version()`).
// The one place the version is written: CMake's project version is read
// from here.
#pragma once

#include <mcdenoise/export.h>

#define MCDENOISE_VERSION_MAJOR 0
#define MCDENOISE_VERSION_MINOR 2
#define MCDENOISE_VERSION_PATCH 0
/// "major.minor.patch".
#define MCDENOISE_VERSION_STRING "0.2.0"
/// The version as one number, major * 10000 + minor * 100 + patch, for
/// comparisons in the preprocessor.
#define MCDENOISE_VERSION                                                                          \
    (MCDENOISE_VERSION_MAJOR * 10000 + MCDENOISE_VERSION_MINOR * 100 + MCDENOISE_VERSION_PATCH)

MCDENOISE_API_BEGIN

/// The version of the libmcdenoise loaded at run time, "major.minor.patch".
/// It differs from `MCDENOISE_VERSION_STRING` when a program runs against
/// another build of the library than the one it was compiled with.
const char* version();

/// The loaded library's version as one number, major * 10000 + minor * 100
/// + patch (`MCDENOISE_VERSION` of the library's own build).
int version_number();

MCDENOISE_API_END
