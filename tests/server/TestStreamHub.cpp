// Stream frames as they go on the wire (issue 15, cheap streaming): every value comes back
// exactly from the JSON text and from the binary message, merged frames keep all samples, and
// subscriptions of a job that stream the same variables share one publication's samples (so
// its JSON text is encoded once for all of them).
#include "ServerHarness.h"
#include "server/jobs/FrameSource.h"
#include "server/jobs/StreamHub.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

using namespace tlmhub::server;
using tlmhub::ResultTable;

namespace {

std::shared_ptr<const FrameSamples> samples(std::vector<double> time, std::vector<std::vector<double>> columns)
{
    auto s = std::make_shared<FrameSamples>();
    s->time = std::move(time);
    s->columns = std::move(columns);
    return s;
}

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Values that a careless formatter loses: negative zero, subnormals, the extremes, long
// mantissas.
const std::vector<double> kAwkward = {0.1, -0.0, 4.9406564584124654e-324, 2.2250738585072014e-308,
                                      1.7976931348623157e308, -123456789.12345679, 1e21, 1e-7, 3.0};

} // namespace

TEST(StreamFrame, JsonAndBinaryCarryEveryValueExactly)
{
    StreamFrame frame;
    frame.jobId = 9;
    frame.layout = std::make_shared<FrameLayout>(std::vector<std::string>{"A#P1#x", "quote\"d"});
    frame.parts.push_back(samples({0.0, 0.5}, {kAwkward, {1.0}}));
    StreamFrame later;
    later.jobId = 9;
    later.layout = frame.layout;
    later.parts.push_back(samples({1.0}, {{std::numeric_limits<double>::quiet_NaN()}, {2.0, 3.0}}));
    frame.append(std::move(later));

    const nlohmann::json fromText = nlohmann::json::parse(frame.jsonText(4));
    const std::string binary = frame.binaryMessage(4);
    EXPECT_LE(frame.jsonText(4).size(), frame.encodedBytesBound(FrameEncoding::Json));
    EXPECT_LE(binary.size(), frame.encodedBytesBound(FrameEncoding::Binary));
    const nlohmann::json fromBinary = tlmhub::test::binaryFrameAsJson(binary);
    for (const auto* e : {&fromText, &fromBinary}) {
        EXPECT_EQ((*e)["type"], "event.frame");
        EXPECT_EQ((*e)["job_id"], 9);
        EXPECT_EQ((*e)["seq"], 4);
        EXPECT_EQ((*e)["dropped"], 1) << "one frame merged into this one";
        EXPECT_EQ((*e)["time"], nlohmann::json({0.0, 0.5, 1.0}));
        EXPECT_EQ((*e)["variables"]["quote\"d"], nlohmann::json({1.0, 2.0, 3.0}));
        const auto& x = (*e)["variables"]["A#P1#x"];
        ASSERT_EQ(x.size(), kAwkward.size() + 1);
        for (std::size_t i = 0; i < kAwkward.size(); ++i)
            EXPECT_TRUE(sameBits(x[i].get<double>(), kAwkward[i])) << i << ": " << x[i].dump();
    }
    EXPECT_TRUE(fromText["variables"]["A#P1#x"].back().is_null()) << "JSON has no NaN";
    EXPECT_TRUE(std::isnan(fromBinary["variables"]["A#P1#x"].back().get<double>())) << "binary keeps it";
}

TEST(StreamHub, SubscriptionsOfTheSameVariablesShareEachPublicationsSamples)
{
    ResultTable table;
    table.time = {0.0, 0.1, 0.2};
    table.columns = {{"A#P1#x", "m", {1, 2, 3}}, {"B#P1#x", "m", {4, 5, 6}}};
    TableFrameSource source(table);

    StreamHub hub;
    std::vector<StreamFrame> frames(4);
    auto sink = [&](std::size_t i) {
        StreamSink s;
        s.progress = [](nlohmann::json) {};
        s.done = [](nlohmann::json) {};
        s.frame = [&frames, i](StreamFrame f) { frames[i] = std::move(f); };
        return s;
    };
    hub.subscribe(1, {"A#P1#x", "B#P1#x"}, 1000, sink(0));
    hub.subscribe(1, {"A#P1#x", "B#P1#x"}, 1000, sink(1));
    hub.subscribe(1, {"B#P1#x"}, 1000, sink(2));
    hub.publishFrames(1, source);
    for (std::size_t i = 0; i < 3; ++i) ASSERT_EQ(frames[i].parts.size(), 1u) << i;
    EXPECT_EQ(frames[0].parts[0], frames[1].parts[0]) << "same variables, same samples: shared";
    EXPECT_EQ(frames[0].layout, frames[1].layout);
    EXPECT_NE(frames[0].parts[0], frames[2].parts[0]);
    EXPECT_EQ(frames[0].jsonText(0), frames[1].jsonText(0));
    EXPECT_EQ(&frames[0].parts[0]->jsonBody(*frames[0].layout), &frames[1].parts[0]->jsonBody(*frames[1].layout))
        << "encoded once";
    EXPECT_EQ(nlohmann::json::parse(frames[2].jsonText(0))["variables"],
              nlohmann::json({{"B#P1#x", {4.0, 5.0, 6.0}}}));

    // A later subscriber starts from the first sample: its samples are its own.
    hub.subscribe(1, {"A#P1#x", "B#P1#x"}, 1000, sink(3));
    hub.finish(1, &source, tlmhub::server::JobState::Done, "");
    ASSERT_EQ(frames[3].parts.size(), 1u);
    EXPECT_EQ(frames[3].layout, frames[0].layout);
    EXPECT_EQ(frames[3].parts[0]->time, table.time);
}
