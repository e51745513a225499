#pragma once
// One block of memory for all logged samples of a system. A large model logs hundreds of
// megabytes; as one block it can be backed by huge pages, so the first run does not pay
// a page fault per 4 KiB of log (about 0.7 s for the x200 bench model on this VM).
#include <cstddef>

namespace tlmhub {

class LogArena {
public:
    LogArena() = default;
    LogArena(const LogArena&) = delete;
    LogArena& operator=(const LogArena&) = delete;
    ~LogArena();

    // Makes room for `values` doubles. Keeps the current block when it has the same
    // capacity (a rerun of the same model), so reruns touch no new memory.
    void reserve(std::size_t values);
    void release();
    double* data() { return mData; }
    std::size_t capacity() const { return mCapacity; }

private:
    double* mData = nullptr;
    std::size_t mCapacity = 0;
    std::size_t mBytes = 0;
};

} // namespace tlmhub
