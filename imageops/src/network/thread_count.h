// thread_count.h: the number of threads oneDNN's primitives run on. Debian's
// oneDNN runs them on OpenMP (libgomp), whose thread count is set per
// calling thread; `ScopedThreadCount` sets it for one network run and puts
// the caller's back. Implemented in thread_count.cpp.
#pragma once

namespace mcdenoise {

/// Sets the OpenMP thread count of the calling thread for its lifetime.
class ScopedThreadCount {
public:
    /// `nthreads` threads, or every hardware thread when it is 0 or less
    /// (the convention of every mcdenoise `nthreads` argument).
    explicit ScopedThreadCount(int nthreads);
    ~ScopedThreadCount();
    ScopedThreadCount(const ScopedThreadCount&)            = delete;
    ScopedThreadCount& operator=(const ScopedThreadCount&) = delete;

private:
    int previous_;
};

}  // namespace mcdenoise
