// The WebSocket send queue: a slow reader's frames merge (no samples lost), past the byte
// limit a stream gives way to its notice, a replaceable message (a job's progress) replaces
// its waiting predecessor, other replies are never dropped, merged or reordered.
#include "server/http/OutgoingQueue.h"

#include <gtest/gtest.h>

#include <memory>

using tlmhub::server::MergeableFrame;
using tlmhub::server::OutgoingMessage;
using tlmhub::server::OutgoingQueue;

namespace {

// A frame of stream `stream` carrying `samples`, written as "s<stream>:<samples>" (with
// "+<merged>" when frames were merged into it); its notice is "resync<stream>".
class FakeFrame final : public MergeableFrame {
public:
    FakeFrame(std::uint64_t stream, std::string samples, std::shared_ptr<bool> givenUp)
        : mStream(stream), mSamples(std::move(samples)), mGivenUp(std::move(givenUp)) {}
    std::uint64_t stream() const override { return mStream; }
    void merge(MergeableFrame& later) override
    {
        auto& other = static_cast<FakeFrame&>(later);
        mSamples += other.mSamples;
        mMerged += other.mMerged + 1;
    }
    std::size_t bytes() const override { return mSamples.size(); }
    // Appended piece by piece: GCC 12 warns (-Wrestrict, falsely) on "s" + std::to_string(...).
    OutgoingMessage message() override
    {
        std::string out = "s";
        out += std::to_string(mStream);
        out += ':';
        out += mSamples;
        if (mMerged) out += '+' + std::to_string(mMerged);
        return {out};
    }
    std::string giveUp() override
    {
        *mGivenUp = true;
        std::string out = "resync";
        out += std::to_string(mStream);
        return out;
    }
    bool streamGivenUp() const override { return *mGivenUp; }

private:
    std::uint64_t mStream;
    std::string mSamples;
    std::uint64_t mMerged = 0;
    std::shared_ptr<bool> mGivenUp;
};

// Frames of one stream, sharing whether it was given up.
struct Stream {
    std::uint64_t id;
    std::shared_ptr<bool> givenUp = std::make_shared<bool>(false);
    std::unique_ptr<MergeableFrame> frame(std::string samples) const
    {
        return std::make_unique<FakeFrame>(id, std::move(samples), givenUp);
    }
};

std::vector<std::string> drain(OutgoingQueue& q)
{
    std::vector<std::string> out;
    while (!q.empty()) {
        out.push_back(q.takeNext().data);
        q.written();
    }
    EXPECT_EQ(q.bytes(), 0u);
    return out;
}

} // namespace

TEST(OutgoingQueue, KeepsEverythingBelowTheLimit)
{
    OutgoingQueue q(4);
    const Stream a{1};
    q.push("reply");
    q.push(a.frame("ab"));
    q.push(a.frame("cd"));
    EXPECT_EQ(q.size(), 3u);
    EXPECT_EQ(drain(q), (std::vector<std::string>{"reply", "s1:ab", "s1:cd"}));
}

TEST(OutgoingQueue, AtTheLimitAFrameMergesIntoItsStreamsLastWaitingFrame)
{
    OutgoingQueue q(3);
    const Stream a{1}, b{2};
    q.push(a.frame("a1"));
    q.push("reply1");
    q.push(b.frame("b1"));
    q.push(a.frame("a2"));   // full: merged into a1, ahead of reply1
    q.push(a.frame("a3"));
    q.push(b.frame("b2"));
    q.push("reply2");        // replies always queue
    EXPECT_EQ(q.size(), 4u);
    EXPECT_EQ(drain(q), (std::vector<std::string>{"s1:a1a2a3+2", "reply1", "s2:b1b2+1", "reply2"}));
}

TEST(OutgoingQueue, AFrameWithNothingOfItsStreamWaitingIsQueuedPastTheLimit)
{
    OutgoingQueue q(2);
    const Stream a{1};
    q.push("reply1");
    q.push("reply2");
    q.push(a.frame("a1"));
    q.push(a.frame("a2"));
    EXPECT_EQ(drain(q), (std::vector<std::string>{"reply1", "reply2", "s1:a1a2+1"}));
}

TEST(OutgoingQueue, TheMessageTakenForWritingIsNoLongerMergedInto)
{
    OutgoingQueue q(1);
    const Stream a{1};
    q.push(a.frame("a1"));
    EXPECT_EQ(q.takeNext().data, "s1:a1");   // being written
    q.push(a.frame("a2"));
    q.push(a.frame("a3"));
    q.written();
    EXPECT_EQ(drain(q), (std::vector<std::string>{"s1:a2a3+1"}));
}

TEST(OutgoingQueue, PastTheByteLimitTheStreamHoldingMostGivesWayToItsNotice)
{
    OutgoingQueue q(2, 20);
    const Stream a{1}, b{2};
    q.push(a.frame("aaaa"));
    q.push(b.frame("bb"));
    q.push(a.frame("aaaaaaaa"));   // merged: 12 + 2 bytes
    q.push("done2");               // 19 bytes
    EXPECT_FALSE(*a.givenUp);
    q.push(a.frame("aaaaaa"));     // 25 bytes: stream 1 goes
    EXPECT_TRUE(*a.givenUp);
    EXPECT_FALSE(*b.givenUp);
    q.push(a.frame("a"));          // a given-up stream's frames are discarded
    q.push("done1");
    EXPECT_FALSE(q.overflowing());
    EXPECT_EQ(drain(q), (std::vector<std::string>{"resync1", "s2:bb", "done2", "done1"}));
}

TEST(OutgoingQueue, AGivenUpStreamLosesAllItsWaitingFramesAndItsNoticeComesFirst)
{
    OutgoingQueue q(10, 16);
    const Stream a{1};
    q.push(a.frame("aaaa"));
    q.push("r1");
    q.push(a.frame("aaaa"));
    q.push("r2");
    q.push(a.frame("aaaaaa"));   // 18 bytes
    EXPECT_EQ(q.bytes(), 7u + 2 + 2);
    EXPECT_EQ(drain(q), (std::vector<std::string>{"resync1", "r1", "r2"}));
}

TEST(OutgoingQueue, RepliesAlonePastTheByteLimitOverflow)
{
    OutgoingQueue q(100, 10);
    const Stream a{1};
    q.push("0123");
    q.push(a.frame("frame"));
    EXPECT_EQ(q.bytes(), 9u);
    q.push("ab");                // 11 bytes: the frame gives way to its notice
    EXPECT_TRUE(*a.givenUp);
    EXPECT_EQ(q.bytes(), 4u + 7 + 2);
    EXPECT_TRUE(q.overflowing());   // replies and notices alone pass the limit
    q.clear();
    EXPECT_EQ(q.bytes(), 0u);
    EXPECT_FALSE(q.overflowing());
}

TEST(OutgoingQueue, TheMessageBeingWrittenCountsUntilWritten)
{
    OutgoingQueue q(10, 10);
    const Stream a{1};
    q.push("abc");
    q.push(a.frame("de"));
    EXPECT_EQ(q.takeNext().data, "abc");
    EXPECT_EQ(q.bytes(), 5u);
    q.push(a.frame("fgh"));    // 8 bytes
    q.push("ijk");             // 11: the frames give way, the message being written stays
    EXPECT_TRUE(*a.givenUp);
    EXPECT_EQ(q.bytes(), 3u + 7 + 3);
    q.written();
    EXPECT_EQ(q.bytes(), 10u);
    EXPECT_FALSE(q.overflowing());
    EXPECT_EQ(drain(q), (std::vector<std::string>{"resync1", "ijk"}));
}

// Progress is a level: a slow reader gets only the latest value per key, in the place of the
// first waiting one, so frames queued after it cannot keep pushing it back.
TEST(OutgoingQueue, AReplaceableMessageReplacesTheWaitingOneWithItsKey)
{
    OutgoingQueue q(3);
    const Stream a{1};
    q.push(a.frame("a1"));
    q.pushReplaceable("job1", "p1=0.1");
    q.push(a.frame("a2"));
    q.pushReplaceable("job2", "p2=0.5");   // another key: queued past the limit, like a reply
    std::string merged = "a2";
    for (char i = '3'; i <= '9'; ++i) {
        const std::string samples{'a', i};
        q.push(a.frame(samples));   // full: merged into a2
        merged += samples;
        q.pushReplaceable("job1", std::string("p1=0.") + i);
    }
    q.push("done1");
    EXPECT_EQ(q.size(), 5u);
    EXPECT_EQ(drain(q), (std::vector<std::string>{"s1:a1", "p1=0.9", "s1:" + merged + "+7", "p2=0.5", "done1"}));
}

TEST(OutgoingQueue, AReplaceableMessageBeingWrittenIsNotReplaced)
{
    OutgoingQueue q(10);
    q.pushReplaceable("job1", "p1=0.1");
    EXPECT_EQ(q.takeNext().data, "p1=0.1");   // being written
    q.pushReplaceable("job1", "p1=0.2");
    q.pushReplaceable("job1", "p1=0.25");
    EXPECT_EQ(q.bytes(), 6u + 7);
    q.written();
    EXPECT_EQ(drain(q), (std::vector<std::string>{"p1=0.25"}));
}
