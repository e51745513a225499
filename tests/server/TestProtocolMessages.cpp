// The generated message structs (server/protocol/Messages.generated.h) hold every field the
// schema defines: each README example survives from_json then to_json unchanged.
#include "ReadmeExamples.h"

#include "server/protocol/Messages.generated.h"

#include <gtest/gtest.h>

#include <functional>
#include <map>

using tlmhub::test::readFile;
using tlmhub::test::readmeExamples;
using nlohmann::json;
namespace protocol = tlmhub::server::protocol;

namespace {

using RoundTrip = std::function<json(const json&)>;

// Definition name -> decode into its struct and encode again.
std::map<std::string, RoundTrip> roundTrips()
{
    std::map<std::string, RoundTrip> out;
    protocol::visitDefinitions([&]<typename T>(const char* name) {
        out[name] = [](const json& value) { return json(value.get<T>()); };
    });
    return out;
}

json schema()
{
    return json::parse(readFile(TLMHUB_SOURCE_DIR "/protocol/messages.schema.json"));
}

std::string definitionName(const json& ref)
{
    const std::string text = ref.get<std::string>();
    return text.substr(text.rfind('/') + 1);
}

} // namespace

TEST(ProtocolMessages, EveryRequestReplyAndServerMessageHasAStruct)
{
    const auto structs = roundTrips();
    const json s = schema();
    for (const char* mapping : {"x-requests", "x-replies", "x-server-messages"})
        for (const auto& [type, ref] : s.at(mapping).items())
            EXPECT_TRUE(structs.count(definitionName(ref))) << mapping << " " << type << ": " << ref.dump();
}

TEST(ProtocolMessages, EveryReadmeExampleRoundTripsThroughItsStruct)
{
    const auto structs = roundTrips();
    const json s = schema();
    auto check = [&](const std::string& definition, const json& value, std::size_t line) {
        const auto roundTrip = structs.find(definition);
        ASSERT_NE(roundTrip, structs.end()) << "README line " << line << ": no struct " << definition;
        EXPECT_EQ(roundTrip->second(value), value) << "README line " << line << " (" << definition << ")";
    };
    std::size_t checked = 0;
    for (const auto& e : readmeExamples()) {
        ++checked;
        if (e.kind == "rest") {
            check(e.argument, e.value, e.line);
            continue;
        }
        const std::string type = e.value.at("type").get<std::string>();
        if (s.at("x-requests").contains(type)) {
            check(definitionName(s.at("x-requests").at(type)), e.value, e.line);
            continue;
        }
        ASSERT_TRUE(s.at("x-server-messages").contains(type)) << "README line " << e.line;
        check(definitionName(s.at("x-server-messages").at(type)), e.value, e.line);
        // A reply's data has the shape x-replies gives for the request.
        if (e.argument.rfind("reply:", 0) == 0)
            check(definitionName(s.at("x-replies").at(e.argument.substr(6))), e.value.at("data"), e.line);
    }
    EXPECT_GT(checked, 50u);
}
