#include "core/LogArena.h"

#include <cstdlib>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace tlmhub {

namespace {
constexpr std::size_t kHugePage = std::size_t(2) << 20;
}

LogArena::~LogArena() { release(); }

void LogArena::release()
{
    std::free(mData);
    mData = nullptr;
    mCapacity = 0;
    mBytes = 0;
}

void LogArena::reserve(std::size_t values)
{
    if (values == mCapacity) return;
    release();
    if (values == 0) return;
    // Not zero-filled: every slot is written before it is read.
    const std::size_t bytes = (values * sizeof(double) + kHugePage - 1) / kHugePage * kHugePage;
    void* p = std::aligned_alloc(kHugePage, bytes);
    if (!p) throw std::bad_alloc();
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    madvise(p, bytes, MADV_HUGEPAGE);   // advice only; without huge pages it still works
#endif
    mData = static_cast<double*>(p);
    mCapacity = values;
    mBytes = bytes;
}

} // namespace tlmhub
