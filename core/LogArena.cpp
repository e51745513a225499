#include "core/LogArena.h"

#include <cstdlib>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace tlmhub {

namespace {
constexpr std::size_t kHugePage = std::size_t(2) << 20;
constexpr std::size_t kCacheLine = 64;
// Below this a log is not worth a huge page (a small model would pay 2 MiB for a few KiB).
constexpr std::size_t kHugePageThreshold = 4 * kHugePage;
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
    const std::size_t wanted = values * sizeof(double);
    const bool huge = wanted >= kHugePageThreshold;
    const std::size_t align = huge ? kHugePage : kCacheLine;
    const std::size_t bytes = (wanted + align - 1) / align * align;
    void* p = std::aligned_alloc(align, bytes);
    if (!p) throw std::bad_alloc();
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    if (huge) madvise(p, bytes, MADV_HUGEPAGE);   // advice only; without huge pages it still works
#endif
    mData = static_cast<double*>(p);
    mCapacity = values;
    mBytes = bytes;
}

} // namespace tlmhub
