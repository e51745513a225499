// Circular FIFO delay buffer (utilities.md §4).
#pragma once

#include <cstddef>
#include <vector>

namespace tlmhub {

template <typename T>
class DelayT
{
public:
    DelayT() { initialize(1, T{}); }

    // N = delaySteps, at least 1; every slot is seeded with init.
    void initialize(int delaySteps, const T& init)
    {
        mSize = (delaySteps < 1) ? 1 : static_cast<std::size_t>(delaySteps);
        mBuf.assign(mSize, init);
        mOldest = 0;
        mNewest = mSize - 1;
    }

    // Steps = round-half-up of timeDelay/Ts.
    void initialize(double timeDelay, double Ts, const T& init)
    {
        initialize(static_cast<int>(timeDelay / Ts + 0.5), init);
    }

    // Pop the oldest, push v; returns the value given N calls earlier.
    T update(const T& v)
    {
        T out = mBuf[mOldest];
        mOldest = (mOldest + 1) % mSize;
        mNewest = (mNewest + 1) % mSize;
        mBuf[mNewest] = v;
        return out;
    }

    const T& getOldest() const { return mBuf[mOldest]; }
    const T& getNewest() const { return mBuf[mNewest]; }

    // 0 = newest, 1 = the one before, ... (wraps, no range check).
    const T& getIdx(std::size_t i) const
    {
        const std::size_t k = i % mSize;
        return mBuf[(mNewest + mSize - k) % mSize];
    }

    // 0 = oldest, 1 = next oldest, ... (wraps).
    const T& getOldIdx(std::size_t i) const { return mBuf[(mOldest + i) % mSize]; }

    std::size_t getSize() const { return mSize; }

private:
    std::vector<T> mBuf;
    std::size_t mSize = 1;
    std::size_t mOldest = 0;
    std::size_t mNewest = 0;
};

using Delay = DelayT<double>;

} // namespace tlmhub
