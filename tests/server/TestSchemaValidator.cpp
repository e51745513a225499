#include "ReadmeExamples.h"
#include "TestFiles.h"

#include "server/protocol/SchemaValidator.h"

#include "core/Catalogue.h"

#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <regex>
#include <set>

using namespace tlmhub::server;
using tlmhub::test::readFile;
using tlmhub::test::ReadmeExample;
using tlmhub::test::readmeExamples;
using nlohmann::json;

namespace {

// A validator over one inline schema whose $defs are the rules under test.
SchemaValidator makeValidator(const json& defs)
{
    SchemaValidator v;
    std::string error;
    EXPECT_TRUE(v.addDocument({{"$id", "test/main"}, {"$defs", defs}}, error)) << error;
    return v;
}

bool accepts(const SchemaValidator& v, const std::string& def, const json& value)
{
    std::string error;
    return v.validate(def, value, error);
}

std::string rejection(const SchemaValidator& v, const std::string& def, const json& value)
{
    std::string error;
    EXPECT_FALSE(v.validate(def, value, error)) << value.dump();
    return error;
}

json protocolFile(const std::string& name)
{
    return json::parse(readFile(TLMHUB_SOURCE_DIR "/protocol/" + name));
}

} // namespace

// ---------------------------------------------------------------- each rule

TEST(SchemaValidator, TypeSingleAndArrayOfTypes)
{
    auto v = makeValidator({{"N", {{"type", "number"}}},
                            {"I", {{"type", "integer"}}},
                            {"SN", {{"type", json::array({"string", "null"})}}}});
    EXPECT_TRUE(accepts(v, "N", 1.5));
    EXPECT_TRUE(accepts(v, "N", 3));
    EXPECT_EQ(rejection(v, "N", "x"), "body: expected number, got string");
    EXPECT_TRUE(accepts(v, "I", 3));
    EXPECT_TRUE(accepts(v, "I", 3.0));   // 2020-12: a number with no fraction is an integer
    EXPECT_EQ(rejection(v, "I", 3.5), "body: expected integer, got number");
    EXPECT_TRUE(accepts(v, "SN", "a"));
    EXPECT_TRUE(accepts(v, "SN", nullptr));
    EXPECT_EQ(rejection(v, "SN", true), "body: expected string or null, got boolean");
}

TEST(SchemaValidator, PropertiesRequiredAndAdditionalProperties)
{
    auto v = makeValidator(
        {{"Closed", {{"type", "object"},
                     {"properties", {{"x", {{"type", "number"}}}, {"y", {{"type", "number"}}}}},
                     {"required", {"x"}},
                     {"additionalProperties", false}}},
         {"Map", {{"type", "object"}, {"additionalProperties", {{"type", "string"}}}}}});
    EXPECT_TRUE(accepts(v, "Closed", {{"x", 1}}));
    EXPECT_TRUE(accepts(v, "Closed", {{"x", 1}, {"y", 2}}));
    EXPECT_EQ(rejection(v, "Closed", {{"y", 2}}), "body: missing required property \"x\"");
    EXPECT_EQ(rejection(v, "Closed", {{"x", "1"}}), "body.x: expected number, got string");
    EXPECT_EQ(rejection(v, "Closed", {{"x", 1}, {"z", 0}}), "body.z: unknown property");
    EXPECT_TRUE(accepts(v, "Map", {{"Comp.Param", "3"}}));
    EXPECT_EQ(rejection(v, "Map", {{"Comp.Param", 3}}), "body[\"Comp.Param\"]: expected string, got integer");
}

TEST(SchemaValidator, ItemsAndItemCounts)
{
    auto v = makeValidator({{"Pair", {{"type", "array"}, {"items", {{"type", "number"}}}, {"minItems", 2}, {"maxItems", 2}}}});
    EXPECT_TRUE(accepts(v, "Pair", {1, 2}));
    EXPECT_EQ(rejection(v, "Pair", {1}), "body: expected at least 2 items, got 1");
    EXPECT_EQ(rejection(v, "Pair", {1, 2, 3}), "body: expected at most 2 items, got 3");
    EXPECT_EQ(rejection(v, "Pair", {1, "b"}), "body[1]: expected number, got string");
}

TEST(SchemaValidator, EnumAndConst)
{
    auto v = makeValidator({{"Role", {{"enum", {"admin", "user"}}}}, {"Ok", {{"const", true}}}});
    EXPECT_TRUE(accepts(v, "Role", "user"));
    EXPECT_EQ(rejection(v, "Role", "root"), "body: expected one of \"admin\", \"user\", got \"root\"");
    EXPECT_TRUE(accepts(v, "Ok", true));
    EXPECT_EQ(rejection(v, "Ok", false), "body: expected true, got false");
}

TEST(SchemaValidator, NumberBounds)
{
    auto v = makeValidator({{"P", {{"type", "number"}, {"minimum", 0}, {"maximum", 1}}},
                            {"Step", {{"type", "number"}, {"exclusiveMinimum", 0}}}});
    EXPECT_TRUE(accepts(v, "P", 0));
    EXPECT_TRUE(accepts(v, "P", 1));
    EXPECT_EQ(rejection(v, "P", -0.5), "body: must be >= 0, got -0.5");
    EXPECT_EQ(rejection(v, "P", 2), "body: must be <= 1, got 2");
    EXPECT_TRUE(accepts(v, "Step", 1e-9));
    EXPECT_EQ(rejection(v, "Step", 0), "body: must be > 0, got 0");
}

TEST(SchemaValidator, StringLengthInCharactersAndPattern)
{
    auto v = makeValidator({{"Short", {{"type", "string"}, {"minLength", 2}, {"maxLength", 3}}},
                            {"Name", {{"type", "string"}, {"pattern", "^[a-z]+$"}}},
                            {"Contains", {{"type", "string"}, {"pattern", "b"}}}});
    EXPECT_TRUE(accepts(v, "Short", "\xC3\xA5\xC3\xA5\xC3\xA5"));   // three characters, six bytes
    EXPECT_EQ(rejection(v, "Short", "a"), "body: must be at least 2 characters long");
    EXPECT_EQ(rejection(v, "Short", "abcd"), "body: must be at most 3 characters long");
    EXPECT_TRUE(accepts(v, "Name", "abc"));
    EXPECT_EQ(rejection(v, "Name", "ab1"), "body: does not match the pattern \"^[a-z]+$\"");
    EXPECT_TRUE(accepts(v, "Contains", "abc"));   // patterns are not anchored
    EXPECT_FALSE(accepts(v, "Contains", "xyz"));
}

TEST(SchemaValidator, OneOfNeedsExactlyOneAnyOfAtLeastOne)
{
    auto v = makeValidator({{"One", {{"oneOf", {{{"required", {"a"}}}, {{"required", {"b"}}}}}}},
                            {"Any", {{"anyOf", {{{"type", "string"}}, {{"type", "integer"}}}}}}});
    EXPECT_TRUE(accepts(v, "One", {{"a", 1}}));
    EXPECT_TRUE(accepts(v, "One", {{"b", 1}}));
    EXPECT_EQ(rejection(v, "One", {{"a", 1}, {"b", 1}}),
              "body: matches 2 of the forms where exactly one is allowed");
    EXPECT_NE(rejection(v, "One", json::object()).find("matches none of the allowed forms"), std::string::npos);
    EXPECT_TRUE(accepts(v, "Any", "s"));
    EXPECT_TRUE(accepts(v, "Any", 1));
    EXPECT_FALSE(accepts(v, "Any", 1.5));
}

TEST(SchemaValidator, RefsWithinAndAcrossDocuments)
{
    SchemaValidator v;
    std::string error;
    ASSERT_TRUE(v.addDocument({{"$id", "test/main"},
                               {"$defs", {{"Pose", {{"type", "object"},
                                                    {"properties", {{"x", {{"$ref", "#/$defs/Coordinate"}}},
                                                                    {"at", {{"$ref", "test/other#/$defs/Time"}}}}}}},
                                          {"Coordinate", {{"type", "number"}}}}}},
                              error));
    ASSERT_TRUE(v.addDocument({{"$id", "test/other"}, {"$defs", {{"Time", {{"type", "number"}, {"minimum", 0}}}}}}, error));
    EXPECT_TRUE(accepts(v, "Pose", {{"x", 1}, {"at", 2}}));
    EXPECT_EQ(rejection(v, "Pose", {{"x", "1"}}), "body.x: expected number, got string");
    EXPECT_EQ(rejection(v, "Pose", {{"at", -1}}), "body.at: must be >= 0, got -1");
    EXPECT_TRUE(accepts(v, "Time", 1));   // a definition of the second document, by name
    EXPECT_FALSE(v.hasDefinition("Nothing"));
    EXPECT_EQ(rejection(v, "Nothing", 1), "no schema definition \"Nothing\"");
}

TEST(SchemaValidator, NestedPathNamesEveryLevel)
{
    auto v = makeValidator({{"M", {{"type", "object"},
                                   {"properties", {{"list", {{"type", "array"},
                                                             {"items", {{"type", "object"},
                                                                        {"properties", {{"pose", {{"$ref", "#/$defs/Pose"}}}}}}}}}}}}},
                            {"Pose", {{"type", "object"}, {"properties", {{"x", {{"type", "number"}}}}}}}});
    EXPECT_EQ(rejection(v, "M", {{"list", {json::object(), {{"pose", {{"x", false}}}}}}}),
              "body.list[1].pose.x: expected number, got boolean");
}

TEST(SchemaValidator, UnknownKeywordsAndBrokenRefsAreReported)
{
    SchemaValidator v;
    std::string error;
    ASSERT_TRUE(v.addDocument({{"$id", "test/main"},
                               {"x-anything", {{"format", 1}}},
                               {"$defs", {{"A", {{"type", "string"}, {"format", "email"}}},
                                          {"B", {{"allOf", json::array()}}},
                                          {"C", {{"$ref", "#/$defs/Missing"}}},
                                          {"D", {{"type", "text"}}},
                                          {"E", {{"type", "object"}, {"properties", {{"p", {{"minLength", 1}}}}}}}}}},
                              error));
    const auto problems = v.unknownKeywords();
    ASSERT_EQ(problems.size(), 4u);
    EXPECT_NE(problems[0].find("test/main#/$defs/A: keyword \"format\""), std::string::npos) << problems[0];
    EXPECT_NE(problems[1].find("\"allOf\""), std::string::npos);
    EXPECT_NE(problems[2].find("$ref \"#/$defs/Missing\" does not resolve"), std::string::npos);
    EXPECT_NE(problems[3].find("unknown type \"text\""), std::string::npos);
}

TEST(SchemaValidator, InvalidPatternRefusesTheDocument)
{
    SchemaValidator v;
    std::string error;
    EXPECT_FALSE(v.addDocument({{"$defs", {{"A", {{"pattern", "(["}}}}}}, error));
    EXPECT_NE(error.find("invalid pattern"), std::string::npos);
}

// ---------------------------------------------------------------- the protocol files

TEST(ProtocolSchema, UsesOnlyTheSupportedSubset)
{
    const auto problems = SchemaValidator::protocol().unknownKeywords();
    for (const auto& p : problems) ADD_FAILURE() << p;
}

TEST(ProtocolSchema, EveryMappingResolvesAndRequestsNameTheirType)
{
    const json schema = protocolFile("messages.schema.json");
    const auto& v = SchemaValidator::protocol();
    ASSERT_FALSE(v.requestTypes().empty());
    for (const char* mapping : {"x-requests", "x-replies", "x-server-messages"})
        for (auto& [type, ref] : schema.at(mapping).items())
            EXPECT_TRUE(v.hasDefinition(ref.get<std::string>())) << mapping << " " << type;
    for (auto& [type, ref] : schema.at("x-requests").items()) {
        const std::string def = ref.get<std::string>().substr(std::string("#/$defs/").size());
        EXPECT_EQ(schema["$defs"][def]["properties"]["type"]["const"], type);
        EXPECT_TRUE(schema.at("x-replies").contains(type)) << "no reply definition for " << type;
    }
    for (auto& [type, ref] : schema.at("x-server-messages").items()) {
        const std::string def = ref.get<std::string>().substr(std::string("#/$defs/").size());
        EXPECT_EQ(schema["$defs"][def]["properties"]["type"]["const"], type);
    }
    // Definitions are PascalCase and titled (the web app generates TypeScript types from them).
    for (auto& [name, def] : schema.at("$defs").items()) {
        EXPECT_TRUE(std::regex_match(name, std::regex("^[A-Z][A-Za-z0-9]*$"))) << name;
        EXPECT_EQ(def.value("title", ""), name);
    }
}

TEST(ProtocolSchema, MalformedMessagesAreRejectedWithPath)
{
    const auto& v = SchemaValidator::protocol();
    std::string code, error;

    EXPECT_FALSE(v.validateMessage(json::array({1}), code, error));
    EXPECT_EQ(code, "schema_violation");
    EXPECT_EQ(error, "message: expected object, got array");

    EXPECT_FALSE(v.validateMessage({{"id", 1}}, code, error));
    EXPECT_EQ(error, "message: missing required property \"type\"");

    EXPECT_FALSE(v.validateMessage({{"id", 1}, {"type", "component.explode"}}, code, error));
    EXPECT_EQ(code, "unknown_message_type");
    EXPECT_NE(error.find("component.explode"), std::string::npos);

    EXPECT_FALSE(v.validateMessage({{"type", "ping"}}, code, error));
    EXPECT_EQ(code, "schema_violation");
    EXPECT_EQ(error, "message: missing required property \"id\"");

    EXPECT_FALSE(v.validateMessage({{"id", 1}, {"type", "component.move"}, {"name", "Mass"},
                                    {"pose", {{"x", "left"}, {"y", 0}, {"angle", 0}, {"flipped", false}}}},
                                   code, error));
    EXPECT_EQ(code, "schema_violation");
    EXPECT_EQ(error, "message.pose.x: expected number, got string");

    EXPECT_FALSE(v.validateMessage({{"id", 1}, {"type", "connect"}, {"from", {{"component", "A"}, {"port", "P1"}}},
                                    {"to", {{"component", "B"}}}},
                                   code, error));
    EXPECT_EQ(error, "message.to: missing required property \"port\"");

    EXPECT_FALSE(v.validateMessage({{"id", 1}, {"type", "ping"}, {"extra", 1}}, code, error));
    EXPECT_EQ(error, "message.extra: unknown property");

    EXPECT_FALSE(v.validateMessage({{"id", 1.5}, {"type", "ping"}}, code, error));
    EXPECT_EQ(error, "message.id: expected integer or string, got number");

    EXPECT_TRUE(v.validateMessage({{"id", "a"}, {"type", "ping"}}, code, error)) << error;
}

TEST(ProtocolSchema, RestBodiesByDefinitionName)
{
    const auto& v = SchemaValidator::protocol();
    std::string error;
    EXPECT_TRUE(v.validate("JobRequest", {{"model_id", 3}}, error)) << error;
    EXPECT_TRUE(v.validate("JobRequest", {{"hmf", "<hopsanmodelfile/>"}, {"parameters", {{"A.k", 2}}}}, error)) << error;
    EXPECT_FALSE(v.validate("JobRequest", {{"model_id", 3}, {"hmf", "x"}}, error));   // exactly one
    EXPECT_FALSE(v.validate("JobRequest", {{"stop", 3}}, error));
    EXPECT_FALSE(v.validate("JobRequest", {{"model_id", 3}, {"parameters", {{"A.k", true}}}}, error));
    EXPECT_NE(error.find("body.parameters[\"A.k\"]"), std::string::npos) << error;
    EXPECT_FALSE(v.validate("UserCreate", {{"username", "bad name"}, {"password", "12345678"}, {"role", "user"}}, error));
    EXPECT_EQ(error, "body.username: does not match the pattern \"^[A-Za-z0-9_.-]{1,64}$\"");
    EXPECT_FALSE(v.validate("PasswordChange", {{"old_password", "x"}, {"new_password", "short"}}, error));
    EXPECT_EQ(error, "body.new_password: must be at least 8 characters long");
    EXPECT_FALSE(v.validate("ModelCreate", {{"name", "a"}, {"hmf", "x"}, {"copy_of", 2}}, error));
}

TEST(ProtocolSchema, CatalogueMatchesItsDefinition)
{
    std::string error;
    EXPECT_TRUE(SchemaValidator::protocol().validate("Catalogue", tlmhub::componentCatalogue(), error)) << error;
}

// ---------------------------------------------------------------- README examples

TEST(ProtocolReadme, EveryExampleValidates)
{
    const auto& v = SchemaValidator::protocol();
    const auto examples = readmeExamples();
    ASSERT_GT(examples.size(), 40u);
    for (const ReadmeExample& e : examples) {
        std::string code, error;
        if (e.kind == "rest") {
            EXPECT_TRUE(v.validate(e.argument, e.value, error)) << "README line " << e.line << ": " << error;
            continue;
        }
        const std::string type = e.value.value("type", "");
        const auto requests = v.requestTypes();
        if (std::find(requests.begin(), requests.end(), type) != requests.end()) {
            EXPECT_TRUE(v.validateMessage(e.value, code, error)) << "README line " << e.line << ": " << error;
        } else {
            const std::string replyTo = e.argument.rfind("reply:", 0) == 0 ? e.argument.substr(6) : "";
            EXPECT_TRUE(v.validateServerMessage(e.value, replyTo, error)) << "README line " << e.line << ": " << error;
        }
    }
}

TEST(ProtocolReadme, HasAnExampleOfEveryMessageAndReply)
{
    const auto& v = SchemaValidator::protocol();
    const json schema = protocolFile("messages.schema.json");
    std::set<std::string> messageTypes, replies;
    for (const ReadmeExample& e : readmeExamples()) {
        if (e.kind != "message") continue;
        messageTypes.insert(e.value.value("type", ""));
        if (e.argument.rfind("reply:", 0) == 0) replies.insert(e.argument.substr(6));
    }
    for (const std::string& type : v.requestTypes()) {
        EXPECT_TRUE(messageTypes.count(type)) << "no README example of request " << type;
        EXPECT_TRUE(replies.count(type)) << "no README example of the reply to " << type;
    }
    for (auto& [type, ref] : schema.at("x-server-messages").items())
        EXPECT_TRUE(messageTypes.count(type)) << "no README example of " << type;
}

TEST(ProtocolReadme, DescribesEveryRestCall)
{
    const std::string readme = readFile(TLMHUB_SOURCE_DIR "/protocol/README.md");
    const json openapi = protocolFile("openapi.json");
    for (auto& [path, item] : openapi.at("paths").items())
        for (auto& [method, op] : item.items()) {
            std::string upper = method;
            for (char& c : upper) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
            const std::string heading = "### " + upper + " /api/v1" + path;
            EXPECT_NE(readme.find(heading + "\n"), std::string::npos) << "README lacks " << heading;
        }
}

// ---------------------------------------------------------------- OpenAPI copy of the shapes

TEST(ProtocolOpenApi, SchemasAreTheMessageSchemaShapes)
{
    const json openapi = protocolFile("openapi.json");
    const json schema = protocolFile("messages.schema.json");
    EXPECT_EQ(openapi.at("openapi").get<std::string>().rfind("3.0", 0), 0u);
    const json& copies = openapi.at("components").at("schemas");
    const json& defs = schema.at("$defs");
    EXPECT_EQ(copies.size(), defs.size()) << "re-run protocol/make-openapi.py";
    for (auto& [name, def] : defs.items()) {
        ASSERT_TRUE(copies.contains(name)) << name << ": re-run protocol/make-openapi.py";
        const json& copy = copies[name];
        const json defProperties = def.value("properties", json::object());
        const json copyProperties = copy.value("properties", json::object());
        std::set<std::string> a, b;
        for (auto& [p, _] : defProperties.items()) a.insert(p);
        for (auto& [p, _] : copyProperties.items()) b.insert(p);
        EXPECT_EQ(a, b) << name << ": re-run protocol/make-openapi.py";
        EXPECT_EQ(def.value("required", json::array()), copy.value("required", json::array())) << name;
    }
    // Every reference in the OpenAPI document points into its own components.
    std::function<void(const json&)> walk = [&](const json& j) {
        if (j.is_object()) {
            if (auto r = j.find("$ref"); r != j.end()) {
                const std::string ref = r->get<std::string>();
                const std::string prefix = "#/components/schemas/";
                ASSERT_EQ(ref.rfind(prefix, 0), 0u) << ref;
                EXPECT_TRUE(copies.contains(ref.substr(prefix.size()))) << ref;
            }
        }
        if (j.is_structured())
            for (const json& child : j) walk(child);
    };
    walk(openapi);
}
