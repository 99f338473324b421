// large_buffer.h: the allocator of the per-image planes (guides, change
// flags, uniform-window maps). Blocks of 4 MiB and more are aligned to
// 2 MiB and advised as transparent huge pages, so touching a fresh plane
// costs a few page faults instead of one per 4 KiB page (at 1080p the page
// faults of the guides' planes cost as much as the filtering itself); new
// elements are left uninitialised, as every plane is written in full.
#pragma once

#include <cstddef>
#include <cstdlib>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

#include <sys/mman.h>

namespace mcdenoise {

/// A std::allocator that puts large blocks on transparent huge pages.
template<class T>
struct LargeBufferAllocator {
    using value_type = T;

    static constexpr size_t huge_page = size_t(2) << 20;
    static constexpr size_t large     = size_t(4) << 20;

    LargeBufferAllocator() = default;
    template<class U>
    LargeBufferAllocator(const LargeBufferAllocator<U>&) noexcept
    {
    }

    T* allocate(size_t n)
    {
        const size_t bytes = n * sizeof(T);
        if (bytes < large)
            return static_cast<T*>(::operator new(bytes));
        const size_t rounded = (bytes + huge_page - 1) / huge_page * huge_page;
        void* p              = std::aligned_alloc(huge_page, rounded);
        if (!p)
            throw std::bad_alloc();
        madvise(p, rounded, MADV_HUGEPAGE);  // advice only: failure is harmless
        return static_cast<T*>(p);
    }

    /// Elements are default-initialised: a plane's values are all written
    /// before they are read, so zeroing them first would be wasted.
    template<class U>
    void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>)
    {
        ::new (static_cast<void*>(p)) U;
    }
    template<class U, class... Args>
    void construct(U* p, Args&&... args)
    {
        ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
    }

    void deallocate(T* p, size_t n) noexcept
    {
        if (n * sizeof(T) < large)
            ::operator delete(p);
        else
            std::free(p);
    }

    template<class U>
    bool operator==(const LargeBufferAllocator<U>&) const noexcept
    {
        return true;
    }
    template<class U>
    bool operator!=(const LargeBufferAllocator<U>&) const noexcept
    {
        return false;
    }
};

/// A vector whose storage comes from `LargeBufferAllocator`.
template<class T>
using LargeVector = std::vector<T, LargeBufferAllocator<T>>;

}  // namespace mcdenoise
