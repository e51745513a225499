// The WebSocket send queue's drop policy: a slow reader loses the oldest stream frames, never
// a reply, and never the message being written.
#include "server/http/OutgoingQueue.h"

#include <gtest/gtest.h>

using tlmhub::server::OutgoingQueue;

namespace {
std::vector<std::string> drain(OutgoingQueue& q)
{
    std::vector<std::string> out;
    while (!q.empty()) {
        out.push_back(q.front());
        q.pop();
    }
    return out;
}
} // namespace

TEST(OutgoingQueue, KeepsEverythingBelowTheLimit)
{
    OutgoingQueue q(4);
    for (const char* m : {"a", "b", "c"}) EXPECT_TRUE(q.push(m, true, false));
    EXPECT_EQ(q.dropped(), 0u);
    EXPECT_EQ(drain(q), (std::vector<std::string>{"a", "b", "c"}));
}

TEST(OutgoingQueue, FullQueueDropsTheOldestFrameNotAReply)
{
    OutgoingQueue q(3);
    q.push("reply1", false, false);
    q.push("frame1", true, false);
    q.push("frame2", true, false);
    EXPECT_TRUE(q.push("reply2", false, false));   // frame1 makes room
    EXPECT_TRUE(q.push("frame3", true, false));    // frame2 makes room
    EXPECT_EQ(q.dropped(), 2u);
    EXPECT_EQ(drain(q), (std::vector<std::string>{"reply1", "reply2", "frame3"}));
}

TEST(OutgoingQueue, TheMessageBeingWrittenIsNeverDropped)
{
    OutgoingQueue q(2);
    q.push("frame-in-flight", true, false);
    q.push("frame2", true, true);
    EXPECT_TRUE(q.push("frame3", true, true));
    EXPECT_EQ(drain(q), (std::vector<std::string>{"frame-in-flight", "frame3"}));
    EXPECT_EQ(q.dropped(), 1u);
}

TEST(OutgoingQueue, OnlyRepliesWaitingMeansTheNewFrameIsDroppedButRepliesStillQueue)
{
    OutgoingQueue q(2);
    q.push("reply1", false, false);
    q.push("reply2", false, false);
    EXPECT_FALSE(q.push("frame", true, false));
    EXPECT_TRUE(q.push("reply3", false, false));   // a reply is never refused
    EXPECT_EQ(q.dropped(), 1u);
    EXPECT_EQ(drain(q), (std::vector<std::string>{"reply1", "reply2", "reply3"}));
}

TEST(OutgoingQueue, PastTheByteLimitFramesGoFirstThenTheQueueOverflows)
{
    OutgoingQueue q(100, 10);
    q.push("0123", false, false);
    q.push("frame", true, false);
    EXPECT_EQ(q.bytes(), 9u);
    EXPECT_TRUE(q.push("ab", false, false));   // 11 bytes: the frame goes, 6 remain
    EXPECT_EQ(q.dropped(), 1u);
    EXPECT_EQ(q.bytes(), 6u);
    EXPECT_FALSE(q.overflowing());
    EXPECT_FALSE(q.push("big-frame", true, false));   // nothing older to drop: it goes itself
    EXPECT_EQ(q.bytes(), 6u);
    EXPECT_TRUE(q.push("reply-5", false, false));     // replies alone pass the limit
    EXPECT_TRUE(q.overflowing());
    q.clear();
    EXPECT_EQ(q.bytes(), 0u);
    EXPECT_FALSE(q.overflowing());
}

TEST(OutgoingQueue, BytesFollowPops)
{
    OutgoingQueue q(10, 1000);
    q.push("abc", false, false);
    q.push("de", true, false);
    q.pop();
    EXPECT_EQ(q.bytes(), 2u);
    q.pop();
    EXPECT_EQ(q.bytes(), 0u);
}
