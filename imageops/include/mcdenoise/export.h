// export.h: MCDENOISE_API, the mark of what libmcdenoise exports.
#pragma once

/// Marks the public API. libmcdenoise is compiled with hidden visibility
/// (`-fvisibility=hidden`); each public header opens its namespace as
/// `namespace mcdenoise MCDENOISE_API {`, so the shared library exports
/// exactly what the public headers declare and none of its internals
/// (imageops/src, whose namespace blocks carry no mark). The static
/// `mcdenoise_internal` library, for the tests of the internals, is built
/// from the same objects.
#define MCDENOISE_API __attribute__((visibility("default")))
