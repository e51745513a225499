// Every REST route of the router and every WebSocket request type of the schema has an
// authorisation case here, and each case runs against a real server: a route or request added
// without one fails the test. The cases: a call without a token is refused (401); a plain user
// calling a route on another user's object (a model, job, study, token, class, assignment or
// hand-in they are not part of) gets 403 or 404; administrator and teacher routes refuse a
// plain user; the rest act only on the caller's own things, which the case says.
#include "ReadmeExamples.h"
#include "ServerHarness.h"
#include "TestFiles.h"

#include "server/api/ApiSupport.h"
#include "server/protocol/SchemaValidator.h"

#include <gtest/gtest.h>

#include <chrono>
#include <map>
#include <thread>

namespace tlmhub::test {
namespace {

namespace http = boost::beast::http;

enum class Case {
    Public,        // no authentication (health, the API description, logging in)
    Own,           // acts on the caller's own account or objects only (the reason is given)
    Foreign,       // on another user's object: 403 or 404
    Administrator, // a plain user: 403
    TeacherRole,   // a plain user (server role user): 403
};

struct RouteCase {
    Case kind;
    std::string why;   // for Own: what keeps it to the caller's own things
};

// "METHOD /pattern" -> its case. A new route needs a line here.
const std::map<std::string, RouteCase>& routeCases()
{
    static const std::map<std::string, RouteCase> cases = {
        {"GET /health", {Case::Public, ""}},
        {"GET /openapi.json", {Case::Public, ""}},
        {"POST /auth/login", {Case::Public, ""}},
        {"GET /auth/providers", {Case::Public, ""}},
        {"GET /auth/oidc/{name}/start", {Case::Public, ""}},
        {"GET /auth/oidc/{name}/callback", {Case::Public, ""}},
        {"POST /auth/oidc/collect", {Case::Public, ""}},
        {"GET /lti/jwks", {Case::Public, ""}},
        {"GET /lti/login", {Case::Public, ""}},
        {"POST /lti/login", {Case::Public, ""}},
        {"POST /lti/launch", {Case::Public, ""}},
        {"GET /lti/app", {Case::Public, ""}},
        {"GET /lti/deep-links/{key}", {Case::Own, "the teacher whose deep-linking launch made the key; 404 for anyone else"}},
        {"POST /lti/deep-links/{key}", {Case::Own, "the teacher whose deep-linking launch made the key; 404 for anyone else"}},
        {"GET /assignments/{id}/lti-scores", {Case::Foreign, ""}},
        {"GET /admin/lti/platforms", {Case::Administrator, ""}},
        {"POST /admin/lti/platforms", {Case::Administrator, ""}},
        {"GET /admin/lti/platforms/{id}", {Case::Administrator, ""}},
        {"PUT /admin/lti/platforms/{id}", {Case::Administrator, ""}},
        {"DELETE /admin/lti/platforms/{id}", {Case::Administrator, ""}},
        {"POST /auth/logout", {Case::Own, "revokes the token it is called with"}},
        {"GET /auth/me", {Case::Own, "the caller's account"}},
        {"POST /auth/password", {Case::Own, "the caller's password, with the old one"}},
        {"POST /auth/download-link", {Case::Own, "a link signed for the caller, checked again when used"}},
        {"GET /components", {Case::Own, "the component catalogue, the same for everyone"}},
        {"GET /preferences", {Case::Own, "the caller's own settings (Preferences test: another user's stay apart)"}},
        {"PUT /preferences", {Case::Own, "replaces the caller's own settings only"}},
        {"GET /stats", {Case::Administrator, ""}},
        {"GET /users", {Case::Administrator, ""}},
        {"POST /users", {Case::Administrator, ""}},
        {"PATCH /users/{id}", {Case::Administrator, ""}},
        {"GET /models", {Case::Own, "lists the caller's models and examples (checked below)"}},
        {"POST /models", {Case::Own, "the new model is the caller's"}},
        {"GET /models/{id}", {Case::Foreign, ""}},
        {"PUT /models/{id}", {Case::Foreign, ""}},
        {"DELETE /models/{id}", {Case::Foreign, ""}},
        {"GET /models/{id}/fmu/interface", {Case::Foreign, ""}},
        {"GET /models/{id}/fmu", {Case::Foreign, ""}},
        {"POST /jobs", {Case::Own, "the job is the caller's; a model_id must be readable (Foreign case below)"}},
        {"GET /jobs", {Case::Own, "lists the caller's jobs; with model_id, the model's runs as GET /jobs/{id} "
                                  "lets the caller see them (RunHistory and Labs tests)"}},
        {"GET /jobs/{id}", {Case::Foreign, ""}},
        {"PATCH /jobs/{id}", {Case::Foreign, ""}},
        {"DELETE /jobs/{id}", {Case::Foreign, ""}},
        {"POST /jobs/{id}/rerun", {Case::Foreign, ""}},
        {"GET /jobs/{id}/results", {Case::Foreign, ""}},
        {"GET /jobs/{id}/variables", {Case::Foreign, ""}},
        {"POST /studies", {Case::Own, "the study is the caller's; a model_id must be readable (Foreign case below)"}},
        {"GET /studies", {Case::Own, "lists the caller's studies"}},
        {"GET /studies/{id}", {Case::Foreign, ""}},
        {"DELETE /studies/{id}", {Case::Foreign, ""}},
        {"POST /studies/{id}/resume", {Case::Foreign, ""}},
        {"GET /studies/{id}/results", {Case::Foreign, ""}},
        {"GET /studies/{id}/runs/{index}/results", {Case::Foreign, ""}},
        {"GET /studies/{id}/bands", {Case::Foreign, ""}},
        {"POST /tokens", {Case::Own, "the token is the caller's"}},
        {"GET /tokens", {Case::Own, "lists the caller's tokens"}},
        {"DELETE /tokens/{id}", {Case::Foreign, ""}},
        {"POST /classes", {Case::TeacherRole, ""}},
        {"GET /classes", {Case::Own, "lists the classes the caller is a member of (checked below)"}},
        {"POST /classes/join", {Case::Own, "joins the caller, and only with the class's code"}},
        {"GET /classes/{id}", {Case::Foreign, ""}},
        {"PATCH /classes/{id}", {Case::Foreign, ""}},
        {"DELETE /classes/{id}", {Case::Foreign, ""}},
        {"POST /classes/{id}/import", {Case::Foreign, ""}},
        {"PUT /classes/{id}/members/{user_id}", {Case::Foreign, ""}},
        {"DELETE /classes/{id}/members/{user_id}", {Case::Foreign, ""}},
        {"GET /classes/{id}/gradebook", {Case::Foreign, ""}},
        {"GET /classes/{id}/live", {Case::Foreign, ""}},
        {"POST /classes/{id}/assignments", {Case::Foreign, ""}},
        {"GET /classes/{id}/assignments", {Case::Foreign, ""}},
        {"GET /assignments/{id}", {Case::Foreign, ""}},
        {"PATCH /assignments/{id}", {Case::Foreign, ""}},
        {"DELETE /assignments/{id}", {Case::Foreign, ""}},
        {"PUT /assignments/{id}/checks", {Case::Foreign, ""}},
        {"GET /assignments/{id}/checks", {Case::Foreign, ""}},
        {"POST /assignments/{id}/open", {Case::Foreign, ""}},
        {"POST /assignments/{id}/reset", {Case::Foreign, ""}},
        {"POST /assignments/{id}/pretest", {Case::Foreign, ""}},
        {"GET /assignments/{id}/pretests/{job}", {Case::Foreign, ""}},
        {"POST /assignments/{id}/handin", {Case::Foreign, ""}},
        {"GET /assignments/{id}/handins", {Case::Foreign, ""}},
        {"GET /assignments/{id}/dashboard", {Case::Foreign, ""}},
        {"GET /assignments/{id}/overlay", {Case::Foreign, ""}},
        {"GET /handins/{id}", {Case::Foreign, ""}},
        {"GET /handins/{id}/model", {Case::Foreign, ""}},
        {"GET /handins/{id}/comments", {Case::Foreign, ""}},
        {"POST /handins/{id}/comments", {Case::Foreign, ""}},
        {"PUT /handins/{id}/grade", {Case::Foreign, ""}},
    };
    return cases;
}

enum class WsCase {
    Own,        // acts on the connection or the caller's own things only
    Foreign,    // names another user's model, job or study: not_found
    OpenModel,  // works on the model this connection opened (model.open checked it): not_open without one
};

const std::map<std::string, WsCase>& wsCases()
{
    static const std::map<std::string, WsCase> cases = {
        {"ping", WsCase::Own},
        {"model.create", WsCase::Own},
        {"model.open", WsCase::Foreign},
        {"simulate.stop", WsCase::Foreign},
        {"log.subscribe", WsCase::Foreign},
        {"study.subscribe", WsCase::Foreign},
        {"study.unsubscribe", WsCase::Own},
        {"model.save", WsCase::OpenModel},
        {"model.get", WsCase::OpenModel},
        {"model.settings", WsCase::OpenModel},
        {"model.controls", WsCase::OpenModel},
        {"component.add", WsCase::OpenModel},
        {"component.remove", WsCase::OpenModel},
        {"component.rename", WsCase::OpenModel},
        {"component.move", WsCase::OpenModel},
        {"connect", WsCase::OpenModel},
        {"disconnect", WsCase::OpenModel},
        {"connection.route", WsCase::OpenModel},
        {"parameter.get", WsCase::OpenModel},
        {"parameter.set", WsCase::OpenModel},
        {"sysparam.set", WsCase::OpenModel},
        {"sysparam.remove", WsCase::OpenModel},
        {"model.group", WsCase::OpenModel},
        {"model.ungroup", WsCase::OpenModel},
        {"simulate.start", WsCase::OpenModel},
        {"live.start", WsCase::Foreign},
        {"live.set", WsCase::Foreign},
        {"live.pause", WsCase::Foreign},
        {"live.resume", WsCase::Foreign},
        {"live.speed", WsCase::Foreign},
        {"live.step", WsCase::Foreign},
        {"live.stop", WsCase::Foreign},
        {"live.record", WsCase::Foreign},
        {"live.subscribe", WsCase::Foreign},
        {"live.share", WsCase::Foreign},
        {"live.unshare", WsCase::Foreign},
        {"live.model", WsCase::Foreign},
    };
    return cases;
}

std::string routeName(const server::RouteSpec& r)
{
    return std::string(http::to_string(r.method)) + " " + r.pattern;
}

TEST(AuthorisationCoverage, EveryRouteAndWebSocketRequestHasACase)
{
    std::set<std::string> routes;
    for (const server::RouteSpec& r : server::apiRoutes()) {
        routes.insert(routeName(r));
        EXPECT_TRUE(routeCases().count(routeName(r))) << routeName(r) << " has no authorisation case";
        if (routeCases().count(routeName(r))) {
            EXPECT_EQ(!r.needsAuth, routeCases().at(routeName(r)).kind == Case::Public) << routeName(r);
        }
    }
    for (const auto& [name, c] : routeCases()) EXPECT_TRUE(routes.count(name)) << name << " is not a route any more";
    const auto types = server::SchemaValidator::protocol().requestTypes();
    for (const std::string& type : types) EXPECT_TRUE(wsCases().count(type)) << type << " has no authorisation case";
    for (const auto& [type, c] : wsCases())
        EXPECT_NE(std::find(types.begin(), types.end(), type), types.end()) << type << " is not a request any more";
}

// sam owns a model, a finished job, a study and a token; tina's class has an assignment and a
// hand-in by sue. olga, a plain user in none of it, tries every route on them.
class AuthorisationCases : public ::testing::Test {
protected:
    void SetUp() override
    {
        server = std::make_unique<ServerProcess>(freshTempDir("authz"));
        createTestUsers(*server, {"sam", "sue", "olga"});
        HttpClient admin = loggedInAs(*server, "admin");
        ASSERT_EQ(admin.post("/api/v1/users", {{"username", "tina"}, {"password", testPassword("tina")}, {"role", "teacher"}})
                      .status,
                  201);
        for (const auto& u : admin.get("/api/v1/users").json()) userIds[u["username"].get<std::string>()] = u["id"].get<std::int64_t>();
        HttpClient sam = loggedInAs(*server, "sam");
        ids["model"] = uploadModel(sam, kPositionServo, "sam-private-model");
        ids["job"] = sam.post("/api/v1/jobs", {{"model_id", ids["model"]}}).json()["id"].get<std::int64_t>();
        waitDone(sam, "/api/v1/jobs/" + std::to_string(ids["job"]));
        const auto study = sam.post("/api/v1/studies", {{"kind", "sweep"}, {"model_id", ids["model"]},
                                                        {"outputs", {{"variables", {"Position_Sensor#out#Value"}}, {"full", true}}},
                                                        {"sweep", {{"parameters", {{"GainP.k", {0.02, 0.03}}}}}}});
        ASSERT_EQ(study.status, 201) << study.body;
        ids["study"] = study.json()["id"].get<std::int64_t>();
        waitDone(sam, "/api/v1/studies/" + std::to_string(ids["study"]));
        ids["token"] = sam.post("/api/v1/tokens", {{"name", "script"}}).json()["id"].get<std::int64_t>();

        HttpClient tina = loggedInAs(*server, "tina");
        const std::int64_t templateId = uploadModel(tina, kPositionServo, "template");
        const auto theClass = tina.post("/api/v1/classes", {{"name", "tina-class"}});
        ids["class"] = theClass.json()["id"].get<std::int64_t>();
        HttpClient sue = loggedInAs(*server, "sue");
        ASSERT_EQ(sue.post("/api/v1/classes/join", {{"code", theClass.json()["join_code"]}}).status, 200);
        const auto assignment = tina.post("/api/v1/classes/" + std::to_string(ids["class"]) + "/assignments",
                                          {{"title", "A"}, {"template_model_id", templateId}, {"solution_model_id", templateId}});
        ASSERT_EQ(assignment.status, 201) << assignment.body;
        ids["assignment"] = assignment.json()["id"].get<std::int64_t>();
        ASSERT_EQ(sue.post("/api/v1/assignments/" + std::to_string(ids["assignment"]) + "/open", nlohmann::json::object()).status, 201);
        const auto handIn = sue.post("/api/v1/assignments/" + std::to_string(ids["assignment"]) + "/handin", nlohmann::json::object());
        ASSERT_EQ(handIn.status, 201) << handIn.body;
        ids["handin"] = handIn.json()["id"].get<std::int64_t>();
    }

    static void waitDone(HttpClient& client, const std::string& path)
    {
        for (int i = 0; i < 400; ++i) {
            const std::string state = client.get(path).json().value("state", "");
            if (state == "done" || state == "failed") return;
            std::this_thread::sleep_for(std::chrono::milliseconds(25));
        }
        ADD_FAILURE() << path << " did not finish";
    }

    // The route's pattern with the ids of sam's (or tina's class's) objects.
    std::string target(const std::string& pattern)
    {
        std::string path = pattern;
        const std::string prefix = path.substr(0, path.find('/', 1));
        const std::map<std::string, std::string> objectOf = {
            {"/models", "model"}, {"/jobs", "job"}, {"/studies", "study"}, {"/tokens", "token"},
            {"/classes", "class"}, {"/assignments", "assignment"}, {"/handins", "handin"}, {"/users", "user"}};
        const auto replace = [&path](const std::string& name, const std::string& value) {
            if (const auto at = path.find(name); at != std::string::npos) path.replace(at, name.size(), value);
        };
        if (const auto object = objectOf.find(prefix); object != objectOf.end())
            replace("{id}", object->second == "user" ? std::to_string(userIds["sam"]) : std::to_string(ids[object->second]));
        replace("{user_id}", std::to_string(userIds["sue"]));
        replace("{index}", "0");
        replace("{job}", std::to_string(ids["job"]));
        return "/api/v1" + path + (path.find("/overlay") != std::string::npos ? "?variable=x" : "");
    }

    // A body the route would accept from someone allowed, so a refusal is about who asks.
    static std::pair<std::string, std::string> plausibleBody(const std::string& name)
    {
        if (name == "PUT /models/{id}") return {readFile(kPositionServo), "application/xml"};
        if (name == "POST /classes/{id}/import") return {"zed\n", "text/csv"};
        if (name == "PATCH /classes/{id}") return {R"({"name": "x"})", "application/json"};
        if (name == "PATCH /assignments/{id}") return {R"({"title": "x"})", "application/json"};
        if (name == "PUT /classes/{id}/members/{user_id}") return {R"({"role": "student"})", "application/json"};
        if (name == "POST /classes/{id}/assignments") return {R"({"title": "x", "template_model_id": 1})", "application/json"};
        if (name == "PUT /assignments/{id}/checks") return {R"({"checks": []})", "application/json"};
        if (name == "POST /handins/{id}/comments") return {R"({"text": "x"})", "application/json"};
        if (name == "PUT /handins/{id}/grade") return {R"({"grade": 1})", "application/json"};
        if (name == "POST /users") return {R"({"username": "x1", "password": "12345678", "role": "user"})", "application/json"};
        if (name == "PATCH /users/{id}") return {R"({"role": "admin"})", "application/json"};
        if (name == "PATCH /jobs/{id}") return {R"({"name": "mine", "pinned": true})", "application/json"};
        if (name == "POST /classes") return {R"({"name": "x"})", "application/json"};
        if (name == "PUT /preferences") return {R"({"units": {"Pressure": "bar"}})", "application/json"};
        if (name == "POST /admin/lti/platforms" || name == "PUT /admin/lti/platforms/{id}")
            return {R"({"name": "x", "issuer": "https://lms.example", "client_id": "c", "auth_url": "https://lms.example/a",
                        "token_url": "https://lms.example/t", "jwks_url": "https://lms.example/k", "deployment_ids": ["1"]})",
                    "application/json"};
        return {"{}", "application/json"};
    }

    std::unique_ptr<ServerProcess> server;
    std::map<std::string, std::int64_t> ids, userIds;
};

TEST_F(AuthorisationCases, EveryRouteRefusesStrangersAndOthersObjects)
{
    HttpClient anonymous(server->port());
    HttpClient olga = loggedInAs(*server, "olga");
    for (const server::RouteSpec& r : server::apiRoutes()) {
        const std::string name = routeName(r);
        const RouteCase& c = routeCases().at(name);
        const std::string path = target(r.pattern);
        const auto [body, type] = plausibleBody(name);
        if (c.kind != Case::Public) {
            const auto reply = anonymous.request(r.method, path, body, type);
            EXPECT_EQ(reply.status, 401) << name << " without a token: " << reply.body;
        }
        if (c.kind == Case::Foreign) {
            const auto reply = olga.request(r.method, path, body, type);
            EXPECT_TRUE(reply.status == 403 || reply.status == 404) << name << " by a stranger: " << reply.status << " " << reply.body;
        }
        if (c.kind == Case::Administrator || c.kind == Case::TeacherRole) {
            const auto reply = olga.request(r.method, path, body, type);
            EXPECT_EQ(reply.status, 403) << name << " by a plain user: " << reply.body;
        }
        if (c.kind == Case::Own) {
            EXPECT_FALSE(c.why.empty()) << name;
        }
    }
    // The lists are the caller's own, and a job or study of another user's model is refused.
    EXPECT_EQ(olga.get("/api/v1/models").body.find("sam-private-model"), std::string::npos);
    EXPECT_EQ(olga.get("/api/v1/classes").body.find("tina-class"), std::string::npos);
    EXPECT_EQ(olga.post("/api/v1/jobs", {{"model_id", ids["model"]}}).status, 404);
    EXPECT_EQ(olga.post("/api/v1/studies", {{"kind", "sweep"}, {"model_id", ids["model"]},
                                            {"outputs", {{"variables", {"Position_Sensor#out#Value"}}}},
                                            {"sweep", {{"parameters", {{"GainP.k", {0.02}}}}}}})
                  .status,
              404);
}

TEST_F(AuthorisationCases, EveryWebSocketRequestRefusesOthersObjects)
{
    HttpClient olga = loggedInAs(*server, "olga");
    // sam's live session, open while olga tries to control it.
    HttpClient sam = loggedInAs(*server, "sam");
    WsClient samSocket(server->port(), sam.token());
    const auto live = samSocket.call("live.start", {{"model_id", ids["model"]}, {"paused", true}});
    ASSERT_EQ(live.value("type", ""), "reply") << live;
    std::map<std::string, nlohmann::json> examples;
    for (const ReadmeExample& e : readmeExamples())
        if (e.kind == "message" && e.argument.empty() && e.value.contains("type") &&
            !examples.count(e.value["type"].get<std::string>()))
            examples[e.value["type"].get<std::string>()] = e.value;
    for (const auto& [type, c] : wsCases()) {
        ASSERT_TRUE(examples.count(type)) << "protocol/README.md has no example of " << type;
        nlohmann::json message = examples[type];
        message.erase("id");
        message.erase("type");
        if (message.contains("model_id")) message["model_id"] = ids["model"];
        if (message.contains("job_id")) message["job_id"] = ids["job"];
        if (message.contains("study_id")) message["study_id"] = ids["study"];
        if (message.contains("session_id")) message["session_id"] = live["data"]["session_id"];
        if (message.contains("class_id")) message["class_id"] = ids["class"];
        WsClient ws(server->port(), olga.token());
        const auto reply = ws.call(type, message);
        ASSERT_FALSE(reply.is_null()) << type << ": no answer";
        if (c == WsCase::Foreign) {
            EXPECT_EQ(reply["error"]["code"], "not_found") << type << ": " << reply;
        }
        if (c == WsCase::OpenModel) {
            EXPECT_EQ(reply["error"]["code"], "not_open") << type << ": " << reply;
        }
    }
}

} // namespace
} // namespace tlmhub::test
