// memory_limit.cpp: memory estimates and the limit they are checked against.
#include "memory_limit.h"

#include "error.h"

#include <OpenImageIO/strutil.h>

#include <cstdio>
#include <limits>
#include <unistd.h>

namespace mcdtool {

using OIIO::Strutil::fmt::format;

namespace {

constexpr uint64_t bytes_per_mebibyte = uint64_t(1) << 20;

/// a * b, or UINT64_MAX if that overflows.
uint64_t saturating_product(uint64_t a, uint64_t b)
{
    uint64_t product = 0;
    return __builtin_mul_overflow(a, b, &product) ? std::numeric_limits<uint64_t>::max() : product;
}

}  // namespace

uint64_t float_bytes(uint64_t pixels, uint64_t channels)
{
    return saturating_product(saturating_product(pixels, channels), sizeof(float));
}

uint64_t memory_limit_bytes(uint64_t limit_mb)
{
    if (limit_mb > 0)
        return saturating_product(limit_mb, bytes_per_mebibyte);
    long pages = sysconf(_SC_PHYS_PAGES);
    long page_size = sysconf(_SC_PAGESIZE);
    if (pages <= 0 || page_size <= 0)
        return std::numeric_limits<uint64_t>::max();
    return saturating_product(uint64_t(pages), uint64_t(page_size));
}

void require_memory(uint64_t bytes, uint64_t limit, const std::string& context, const std::string& what)
{
    if (bytes <= limit)
        return;
    std::string need = bytes == std::numeric_limits<uint64_t>::max()
                           ? std::string("more memory than a 64-bit size can count")
                           : format("{} MiB", (bytes + bytes_per_mebibyte - 1) / bytes_per_mebibyte);
    throw RunError(format("{} : {} needs {}, more than the memory limit of {} MiB (--memory-limit)", context,
                          what, need, limit / bytes_per_mebibyte));
}

uint64_t resident_bytes()
{
    std::FILE* statm = std::fopen("/proc/self/statm", "r");
    if (!statm)
        return 0;
    unsigned long long total = 0, resident = 0;
    const bool read = std::fscanf(statm, "%llu %llu", &total, &resident) == 2;
    std::fclose(statm);
    const long page = sysconf(_SC_PAGESIZE);
    return read && page > 0 ? uint64_t(resident) * uint64_t(page) : 0;
}

}  // namespace mcdtool
