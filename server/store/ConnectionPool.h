#pragma once
// A bounded pool of database connections shared by every thread. A caller leases one for one
// store call (or one transaction) and gives it back; idle connections are reused most recent
// first, so a busy thread tends to find the connection it used last and its prepared
// statements. At most `maxConnections` are open; beyond that callers wait for one.
#include <condition_variable>
#include <cstddef>
#include <functional>
#include <memory>
#include <mutex>
#include <utility>
#include <vector>

namespace tlmhub::server {

template <typename Connection>
class ConnectionPool {
public:
    using Factory = std::function<std::unique_ptr<Connection>()>;

    ConnectionPool(Factory open, unsigned maxConnections)
        : mOpen(std::move(open)), mMax(maxConnections == 0 ? 1 : maxConnections)
    {
    }
    ConnectionPool(const ConnectionPool&) = delete;
    ConnectionPool& operator=(const ConnectionPool&) = delete;

    class Lease {
    public:
        Lease(ConnectionPool& pool, std::unique_ptr<Connection> c) : mPool(&pool), mConnection(std::move(c)) {}
        Lease(Lease&& other) noexcept = default;
        Lease& operator=(Lease&&) = delete;
        ~Lease()
        {
            if (mConnection) mPool->giveBack(std::move(mConnection), mBroken);
        }
        Connection& operator*() const { return *mConnection; }
        Connection* operator->() const { return mConnection.get(); }
        // The connection is not to be used again (e.g. the server closed it): it is closed
        // instead of going back to the pool.
        void discard() { mBroken = true; }

    private:
        ConnectionPool* mPool;
        std::unique_ptr<Connection> mConnection;
        bool mBroken = false;
    };

    Lease acquire()
    {
        std::unique_lock lock(mMutex);
        mReturned.wait(lock, [&] { return !mIdle.empty() || mOpenCount < mMax; });
        if (!mIdle.empty()) {
            auto c = std::move(mIdle.back());
            mIdle.pop_back();
            return Lease(*this, std::move(c));
        }
        ++mOpenCount;
        lock.unlock();
        try {
            return Lease(*this, mOpen());
        } catch (...) {
            lock.lock();
            --mOpenCount;
            mReturned.notify_one();
            throw;
        }
    }

    std::size_t openConnections() const
    {
        std::lock_guard lock(mMutex);
        return mOpenCount;
    }

private:
    void giveBack(std::unique_ptr<Connection> c, bool broken)
    {
        std::unique_ptr<Connection> closing;   // closed outside the lock
        {
            std::lock_guard lock(mMutex);
            if (broken) {
                closing = std::move(c);
                --mOpenCount;
            } else {
                mIdle.push_back(std::move(c));
            }
        }
        mReturned.notify_one();
    }

    Factory mOpen;
    const unsigned mMax;
    mutable std::mutex mMutex;
    std::condition_variable mReturned;
    std::vector<std::unique_ptr<Connection>> mIdle;
    unsigned mOpenCount = 0;
};

} // namespace tlmhub::server
