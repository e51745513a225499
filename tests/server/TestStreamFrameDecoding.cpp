// decodeBinaryFrame, the inverse of StreamFrame::binaryMessage: what a node that relays
// another node's stream reads. Round trips give back every sample bit for bit; malformed
// messages are refused with a reason. The fuzz target binary-frame starts from the seeds
// these messages make (fuzz/corpus/binary-frame, kept current by the last test).
#include "server/jobs/StreamFrameDecoding.h"

#include "TestFiles.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>

using namespace tlmhub::server;
namespace fs = std::filesystem;

namespace {

std::shared_ptr<FrameSamples> part(std::vector<double> time, std::vector<std::vector<double>> columns)
{
    auto p = std::make_shared<FrameSamples>();
    p->time = std::move(time);
    p->columns = std::move(columns);
    return p;
}

// Three parts merged (as a slow socket's queue merges them); "b" lags the time vector by one
// sample in the first part and catches up in the second.
StreamFrame mergedFrame()
{
    StreamFrame f;
    f.jobId = 41;
    f.layout = std::make_shared<const FrameLayout>(std::vector<std::string>{"Mass#P2#Position", "b", "quote\"d"});
    f.parts.push_back(part({0, 0.5, 1}, {{1, 2, 3}, {-0.0, 4}, {7, 8, 9}}));
    StreamFrame second;
    second.jobId = 41;
    second.layout = f.layout;
    second.parts.push_back(part({1.5}, {{std::nan("")}, {5, 6}, {10}}));
    f.append(std::move(second));
    StreamFrame third;
    third.jobId = 41;
    third.layout = f.layout;
    third.parts.push_back(part({2, 2.5}, {{std::numeric_limits<double>::infinity(), 1e-308}, {7, 8}, {11, 12}}));
    f.append(std::move(third));
    return f;
}

bool sameBits(const std::vector<double>& a, const std::vector<double>& b)
{
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

// The samples of every part, concatenated per column ("" is time).
std::map<std::string, std::vector<double>> columnsOf(const StreamFrame& f)
{
    std::map<std::string, std::vector<double>> out;
    for (const auto& p : f.parts) {
        out[""].insert(out[""].end(), p->time.begin(), p->time.end());
        for (std::size_t i = 0; i < f.layout->names.size(); ++i)
            if (i < p->columns.size())
                out[f.layout->names[i]].insert(out[f.layout->names[i]].end(), p->columns[i].begin(), p->columns[i].end());
    }
    return out;
}

// A message with `header` as its header text and `values` float64s after it.
std::string messageWith(const std::string& header, std::size_t values, char padding = '\0')
{
    const auto headerBytes = static_cast<std::uint32_t>(header.size());
    const std::size_t dataOffset = (4 + header.size() + 7) / 8 * 8;
    std::string m(dataOffset + values * 8, '\0');
    std::memcpy(m.data(), &headerBytes, 4);
    std::memcpy(m.data() + 4, header.data(), header.size());
    for (std::size_t i = 4 + header.size(); i < dataOffset; ++i) m[i] = padding;
    return m;
}

std::string refusal(const std::string& message)
{
    DecodedFrame out;
    std::string error;
    EXPECT_FALSE(decodeBinaryFrame(message, out, error));
    return error;
}

const std::string kGoodHeader =
    R"({"type":"event.frame","job_id":3,"seq":0,"dropped":0,"time_samples":2,"variables":[{"name":"a","samples":2}]})";

// The seeds of the fuzz target: merged and single frames, empty ones, and a malformed one.
std::map<std::string, std::string> seedMessages()
{
    std::map<std::string, std::string> seeds;
    seeds["merged"] = mergedFrame().binaryMessage(7);
    StreamFrame empty;
    empty.jobId = 1;
    empty.layout = std::make_shared<const FrameLayout>(std::vector<std::string>{});
    empty.parts.push_back(part({}, {}));
    seeds["empty"] = empty.binaryMessage(0);
    StreamFrame single;
    single.jobId = 9;
    single.layout = std::make_shared<const FrameLayout>(std::vector<std::string>{"Step#out#Value"});
    single.parts.push_back(part({0, 0.001, 0.002}, {{0, 1, 1}}));
    seeds["single"] = single.binaryMessage(123456);
    seeds["truncated"] = seeds["single"].substr(0, seeds["single"].size() - 5);
    return seeds;
}

} // namespace

TEST(StreamFrameDecoding, AMergedFrameComesBackSampleForSample)
{
    const StreamFrame sent = mergedFrame();
    DecodedFrame got;
    std::string error;
    ASSERT_TRUE(decodeBinaryFrame(sent.binaryMessage(7), got, error)) << error;
    EXPECT_EQ(got.seq, 7u);
    EXPECT_EQ(got.dropped, 2u);
    EXPECT_EQ(got.frame.jobId, 41);
    EXPECT_EQ(got.frame.merged, 0u);
    ASSERT_EQ(got.frame.parts.size(), 1u) << "one part holds the merged frame's samples";
    EXPECT_EQ(got.frame.layout->names, sent.layout->names);
    const auto expected = columnsOf(sent);
    const auto decoded = columnsOf(got.frame);
    ASSERT_EQ(decoded.size(), expected.size());
    for (const auto& [name, values] : expected) EXPECT_TRUE(sameBits(decoded.at(name), values)) << name;
    EXPECT_EQ(decoded.at("b").size(), decoded.at("").size()) << "b caught up";
    // Encoded again (with its count of merged frames), it is the same message.
    got.frame.merged = got.dropped;
    EXPECT_EQ(got.frame.binaryMessage(7), sent.binaryMessage(7));
}

TEST(StreamFrameDecoding, AColumnOneSampleShorterThanTimeStaysShorter)
{
    StreamFrame f;
    f.jobId = 5;
    f.layout = std::make_shared<const FrameLayout>(std::vector<std::string>{"x", "y"});
    f.parts.push_back(part({0, 1, 2, 3}, {{1, 2, 3}, {4, 5, 6, 7}}));
    DecodedFrame got;
    std::string error;
    ASSERT_TRUE(decodeBinaryFrame(f.binaryMessage(0), got, error)) << error;
    EXPECT_EQ(got.frame.parts[0]->time.size(), 4u);
    EXPECT_TRUE(sameBits(got.frame.parts[0]->columns[0], {1, 2, 3}));
    EXPECT_TRUE(sameBits(got.frame.parts[0]->columns[1], {4, 5, 6, 7}));
}

TEST(StreamFrameDecoding, MalformedMessagesAreRefusedWithAReason)
{
    const std::string good = messageWith(kGoodHeader, 4);
    DecodedFrame out;
    std::string error;
    ASSERT_TRUE(decodeBinaryFrame(good, out, error)) << error;

    EXPECT_NE(refusal(""), "");
    EXPECT_NE(refusal("\x05\x00\x00"), "");
    // Truncated: in the header, in the padding, in the samples; one sample too many.
    EXPECT_NE(refusal(good.substr(0, 20)).find("header length past the end"), std::string::npos);
    EXPECT_NE(refusal(good.substr(0, 4 + kGoodHeader.size() + 1)), "");
    EXPECT_NE(refusal(good.substr(0, good.size() - 8)).find("more than the message holds"), std::string::npos);
    EXPECT_NE(refusal(good.substr(0, good.size() - 3)).find("whole float64s"), std::string::npos);
    EXPECT_NE(refusal(good + std::string(8, '\0')).find("more samples than its header counts"), std::string::npos);
    // An absurd header length, and absurd counts (nothing is allocated for them).
    std::string huge = good;
    const std::uint32_t absurd = 0xFFFFFFF0u;
    std::memcpy(huge.data(), &absurd, 4);
    EXPECT_NE(refusal(huge), "");
    EXPECT_NE(refusal(messageWith(R"({"type":"event.frame","job_id":3,"seq":0,"dropped":0,"time_samples":18446744073709551615,"variables":[]})", 2)),
              "");
    EXPECT_NE(refusal(messageWith(R"({"type":"event.frame","job_id":3,"seq":0,"dropped":0,"time_samples":1,"variables":[{"name":"a","samples":9223372036854775807},{"name":"b","samples":9223372036854775807}]})", 1)),
              "");
    // Non-zero padding.
    EXPECT_NE(refusal(messageWith(kGoodHeader, 4, 'x')).find("padding"), std::string::npos);
    // Header fields: wrong types, missing, unknown, negative, fractional, duplicate names.
    const std::vector<std::string> badHeaders = {
        "not json",
        "[1,2]",
        R"({"type":"event.done","job_id":3,"seq":0,"dropped":0,"time_samples":2,"variables":[{"name":"a","samples":2}]})",
        R"({"job_id":3,"seq":0,"dropped":0,"time_samples":2,"variables":[{"name":"a","samples":2}]})",
        R"({"type":"event.frame","job_id":"3","seq":0,"dropped":0,"time_samples":2,"variables":[{"name":"a","samples":2}]})",
        R"({"type":"event.frame","job_id":0,"seq":0,"dropped":0,"time_samples":2,"variables":[{"name":"a","samples":2}]})",
        R"({"type":"event.frame","job_id":3,"seq":-1,"dropped":0,"time_samples":2,"variables":[{"name":"a","samples":2}]})",
        R"({"type":"event.frame","job_id":3,"seq":0,"dropped":0.5,"time_samples":2,"variables":[{"name":"a","samples":2}]})",
        R"({"type":"event.frame","job_id":3,"seq":0,"dropped":0,"time_samples":2.0,"variables":[{"name":"a","samples":2}]})",
        R"({"type":"event.frame","job_id":3,"seq":0,"dropped":0,"time_samples":2,"variables":{"a":2}})",
        R"({"type":"event.frame","job_id":3,"seq":0,"dropped":0,"time_samples":2,"variables":[{"name":1,"samples":2}]})",
        R"({"type":"event.frame","job_id":3,"seq":0,"dropped":0,"time_samples":2,"variables":[{"name":"a","samples":"2"}]})",
        R"({"type":"event.frame","job_id":3,"seq":0,"dropped":0,"time_samples":2,"variables":[{"name":"a"}]})",
        R"({"type":"event.frame","job_id":3,"seq":0,"dropped":0,"time_samples":2,"variables":[{"name":"a","samples":2,"unit":"m"}]})",
        R"({"type":"event.frame","job_id":3,"seq":0,"dropped":0,"time_samples":2,"variables":[{"name":"a","samples":2}],"extra":1})",
        R"({"type":"event.frame","job_id":3,"seq":0,"dropped":0,"time_samples":2,"variables":[[[[[[1]]]]]]})",
        R"({"type":"event.frame","job_id":3,"seq":0,"dropped":0,"time_samples":0,"variables":[{"name":"a","samples":2},{"name":"a","samples":0}]})",
    };
    for (const auto& header : badHeaders) EXPECT_NE(refusal(messageWith(header, 4)), "") << header;
}

// fuzz/corpus/binary-frame holds seedMessages(); TLMHUB_UPDATE_FUZZ_SEEDS=1 rewrites it.
TEST(StreamFrameDecoding, TheFuzzSeedsAreCurrent)
{
    const fs::path dir = fs::path(TLMHUB_SOURCE_DIR) / "fuzz" / "corpus" / "binary-frame";
    const bool update = std::getenv("TLMHUB_UPDATE_FUZZ_SEEDS") != nullptr;
    if (update) fs::create_directories(dir);
    for (const auto& [name, message] : seedMessages()) {
        if (update) std::ofstream(dir / name, std::ios::binary) << message;
        EXPECT_EQ(tlmhub::test::readFile(dir / name), message)
            << name << ": run this test with TLMHUB_UPDATE_FUZZ_SEEDS=1 to write the seeds";
    }
}
