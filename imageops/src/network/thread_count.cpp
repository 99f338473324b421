// thread_count.cpp: OpenMP's thread count around a network run
// (thread_count.h). The two OpenMP runtime functions are declared here, by
// their standard C signatures, rather than through <omp.h>: the library is
// built by GCC and (for fuzzing) by Clang, whose <omp.h> belongs to another
// runtime than the libgomp oneDNN is linked with.
#include "network/thread_count.h"

#include <thread>

extern "C" {
int omp_get_max_threads(void);
void omp_set_num_threads(int);
}

namespace mcdenoise {

ScopedThreadCount::ScopedThreadCount(int nthreads)
    : previous_(omp_get_max_threads())
{
    const int all = int(std::thread::hardware_concurrency());
    omp_set_num_threads(nthreads > 0 ? nthreads : (all > 0 ? all : 1));
}

ScopedThreadCount::~ScopedThreadCount() { omp_set_num_threads(previous_); }

}  // namespace mcdenoise
