// export.h: MCDENOISE_API_BEGIN / MCDENOISE_API_END, the marks of what
// libmcdenoise exports.
#pragma once

/// Open and close the public API's namespace. libmcdenoise is compiled with
/// hidden visibility (`-fvisibility=hidden`); each public header declares
/// its functions between `MCDENOISE_API_BEGIN` and `MCDENOISE_API_END`,
/// which give those declarations default visibility, so the shared library
/// exports exactly what the public headers declare and none of its
/// internals (imageops/src, whose namespace blocks carry no mark). A
/// visibility pragma rather than an attribute on the namespace: Clang
/// applies a namespace's attribute only to the block that carries it, not
/// to the definitions in the sources' own `namespace mcdenoise` blocks. The
/// static `mcdenoise_internal` library, for the tests of the internals, is
/// built from the same objects.
#define MCDENOISE_API_BEGIN _Pragma("GCC visibility push(default)") namespace mcdenoise {
#define MCDENOISE_API_END } _Pragma("GCC visibility pop")
