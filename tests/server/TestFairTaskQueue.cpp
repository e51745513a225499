// Lab check runs take turns between users (issue 37 M2): four slow pretests of one student
// held another's for 46 s on a first-come pool. Tasks here block until the test lets them go,
// so the order they start in is the queue's, not the machine's.
#include "server/app/FairTaskQueue.h"

#include <gtest/gtest.h>

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <set>
#include <string>
#include <vector>

namespace tlmhub::server {
namespace {

// Records which tasks started, in order; each task waits until released by name.
class BlockingTasks {
public:
    std::function<void()> task(const std::string& name)
    {
        return [this, name] {
            std::unique_lock lock(mMutex);
            mStarted.push_back(name);
            mChanged.notify_all();
            mChanged.wait(lock, [&] { return mReleased.count(name) > 0; });
        };
    }
    void release(const std::string& name)
    {
        std::lock_guard lock(mMutex);
        mReleased.insert(name);
        mChanged.notify_all();
    }
    // Waits (at most 60 s) until `count` tasks have started; the names in order.
    std::vector<std::string> started(std::size_t count)
    {
        std::unique_lock lock(mMutex);
        mChanged.wait_for(lock, std::chrono::seconds(60), [&] { return mStarted.size() >= count; });
        return mStarted;
    }

private:
    std::mutex mMutex;
    std::condition_variable mChanged;
    std::vector<std::string> mStarted;
    std::set<std::string> mReleased;
};

TEST(FairTaskQueue, AUserWhoHasNotRunGoesAheadOfAnotherUsersWaitingTasks)
{
    BlockingTasks tasks;
    FairTaskQueue queue(1, 1, 10);
    ASSERT_TRUE(queue.submit(1, tasks.task("a1")));
    ASSERT_EQ(tasks.started(1), std::vector<std::string>{"a1"});
    for (const char* name : {"a2", "a3"}) ASSERT_TRUE(queue.submit(1, tasks.task(name)));
    ASSERT_TRUE(queue.submit(2, tasks.task("b1")));
    for (const char* name : {"a1", "b1", "a2", "a3"}) tasks.release(name);
    EXPECT_EQ(tasks.started(4), (std::vector<std::string>{"a1", "b1", "a2", "a3"}));
}

TEST(FairTaskQueue, AUserRunsAtMostTheirCapAndWaitsAtMostTheQueueLimit)
{
    BlockingTasks tasks;
    FairTaskQueue queue(3, 2, 2);
    for (const char* name : {"a1", "a2", "a3", "a4"}) ASSERT_TRUE(queue.submit(1, tasks.task(name))) << name;
    EXPECT_FALSE(queue.submit(1, tasks.task("a5"))) << "two running and two waiting: the fifth is refused";
    ASSERT_TRUE(queue.submit(2, tasks.task("b1")));
    // a3 waits for one of a1 and a2 although a thread is free: b1 takes it. Three threads pick
    // up a1, a2 and b1 at once, so the order they start in is the scheduler's: compare as a set.
    const std::vector<std::string> firstThree = tasks.started(3);
    EXPECT_EQ(std::set<std::string>(firstThree.begin(), firstThree.end()),
              (std::set<std::string>{"a1", "a2", "b1"}));
    tasks.release("a1");
    EXPECT_EQ(tasks.started(4).back(), "a3");
    EXPECT_TRUE(queue.submit(1, tasks.task("a5"))) << "room to wait again";
    for (const char* name : {"a2", "a3", "a4", "a5", "b1"}) tasks.release(name);
    EXPECT_EQ(tasks.started(6).size(), 6u);
}

} // namespace
} // namespace tlmhub::server
