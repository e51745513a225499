// Each account's own settings through a real server (issue 38 item 4): GET /preferences gives
// the display units a user chose, PUT replaces them; one user's never show for another, they
// outlive a restart, and bodies past the limits are refused naming what is wrong.
#include "ServerHarness.h"

#include <gtest/gtest.h>

#include <string>

namespace tlmhub::test {

namespace {

namespace http = boost::beast::http;

HttpReply putPreferences(HttpClient& client, const nlohmann::json& body)
{
    return client.request(http::verb::put, "/api/v1/preferences", body.dump());
}

TEST(Preferences, EachUserKeepsTheirOwnDisplayUnitsAcrossARestart)
{
    const auto dir = freshTempDir("preferences");
    const nlohmann::json chosen = {{"units", {{"Pressure", "bar"}, {"Flow", "l/min"}, {"Temperature", "C"}}}};
    {
        ServerProcess server(dir);
        createTestUsers(server, {"hana", "ivo"});
        HttpClient hana = loggedInAs(server, "hana"), ivo = loggedInAs(server, "ivo");
        const auto fresh = hana.get("/api/v1/preferences");
        ASSERT_EQ(fresh.status, 200) << fresh.body;
        EXPECT_EQ(fresh.json(), nlohmann::json({{"units", nlohmann::json::object()}}));

        const auto stored = putPreferences(hana, chosen);
        ASSERT_EQ(stored.status, 200) << stored.body;
        EXPECT_EQ(stored.json(), chosen);
        EXPECT_EQ(hana.get("/api/v1/preferences").json(), chosen);
        EXPECT_EQ(ivo.get("/api/v1/preferences").json()["units"], nlohmann::json::object()) << "another user's units";

        // Refused whole, naming the limit; what was stored stays.
        nlohmann::json many = {{"units", nlohmann::json::object()}};
        for (int i = 0; i < 101; ++i) many["units"]["Quantity" + std::to_string(i)] = "x";
        const auto tooMany = putPreferences(hana, many);
        EXPECT_EQ(tooMany.status, 400) << tooMany.body;
        EXPECT_NE(tooMany.body.find("at most 100"), std::string::npos) << tooMany.body;
        EXPECT_EQ(putPreferences(hana, {{"units", {{"", "bar"}}}}).status, 400);
        EXPECT_EQ(putPreferences(hana, {{"units", {{"Pressure", std::string(41, 'b')}}}}).status, 400);
        EXPECT_EQ(putPreferences(hana, {{"units", {{"Pressure", 1e5}}}}).status, 400);
        EXPECT_EQ(putPreferences(hana, {{"colours", "dark"}}).status, 400);
        EXPECT_EQ(hana.request(http::verb::put, "/api/v1/preferences", "{\"units\":").status, 400);
        EXPECT_EQ(hana.get("/api/v1/preferences").json(), chosen);

        HttpClient nobody(server.port());
        EXPECT_EQ(nobody.get("/api/v1/preferences").status, 401);
        EXPECT_EQ(putPreferences(nobody, chosen).status, 401);
    }
    ServerProcess again(dir);
    HttpClient hana = loggedInAs(again, "hana");
    EXPECT_EQ(hana.get("/api/v1/preferences").json(), chosen);
}

} // namespace
} // namespace tlmhub::test
