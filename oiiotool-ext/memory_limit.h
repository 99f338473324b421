// memory_limit.h: the memory mcdtool may use. Every image's size is checked
// against the limit (--memory-limit, default the machine's physical memory)
// from its header, before its pixels are allocated, and a frame's working
// set is checked before the filters run, so a render too large for memory
// is a clear error naming the file rather than an allocation failure.
#pragma once

#include <cstdint>
#include <string>

namespace mcdtool {

/// Bytes of `pixels` pixels of `channels` float channels, saturating at
/// UINT64_MAX instead of overflowing.
uint64_t float_bytes(uint64_t pixels, uint64_t channels);

/// The memory limit in bytes: `limit_mb` MiB, or the machine's physical
/// memory when `limit_mb` is 0.
uint64_t memory_limit_bytes(uint64_t limit_mb);

/// The process's resident memory now, in bytes (Linux /proc/self/statm;
/// 0 where it cannot be read).
uint64_t resident_bytes();

/// Throws RunError "<context> : <what> needs N MiB, more than the memory
/// limit of L MiB (--memory-limit)" if `bytes` exceeds `limit`.
void require_memory(uint64_t bytes, uint64_t limit, const std::string& context, const std::string& what);

}  // namespace mcdtool
