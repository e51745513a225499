// tlmhub as an LTI 1.3 tool against a platform (issue 43 item 3): the test platform on npm's
// jose (tests/peers/lti-platform), started by the test over TLS on loopback and registered
// through the administrators' API. A launch goes the way a browser takes it: the platform's
// third-party-initiated login at the tool, the tool's redirect (with its state cookie) to the
// platform's authentication address, the platform's form post of the signed message back to the
// tool, and the app's one-time hand-over. Checked: a teacher's first launch makes the course's
// class, a student's launch joins it with the class role the launch's roles give; each check
// LTI 1.3 Core requires refuses a launch broken in exactly that one way; a launch is taken
// once and only in the browser its login came through; a platform's rotated key is fetched; the
// registry is for administrators only; the launch page may be framed by registered platforms.
#include "ServerHarness.h"
#include "TemporaryLtiPlatform.h"
#include "TestFiles.h"

#include "server/auth/lti/ToolKeys.h"
#include "server/auth/oidc/JsonWebKeySet.h"
#include "server/auth/oidc/JwsSignature.h"
#include "server/auth/oidc/Base64Url.h"
#include "server/http/Router.h"
#include "net/Url.h"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <thread>

using tlmhub::test::HttpClient;
using tlmhub::test::HttpReply;
using tlmhub::test::ServerProcess;
using tlmhub::test::TemporaryLtiPlatform;
namespace http = boost::beast::http;

namespace {

// A new RSA key of the tool in a file only its owner may read.
std::filesystem::path newToolKey(const std::filesystem::path& file)
{
    const std::string command = "/usr/bin/openssl genpkey -algorithm RSA -pkeyopt rsa_keygen_bits:2048 -out '" +
                                file.string() + "' >/dev/null 2>&1";
    if (std::system(command.c_str()) != 0) throw std::runtime_error("openssl genpkey failed");
    std::filesystem::permissions(file, std::filesystem::perms::owner_read | std::filesystem::perms::owner_write);
    return file;
}

// The form fields of a launch as a form post's body.
std::string formBody(const nlohmann::json& fields)
{
    std::string body;
    for (const char* name : {"id_token", "state", "error"})
        if (fields.contains(name))
            body += std::string(body.empty() ? "" : "&") + name + "=" + tlmhub::net::percentEncode(fields[name].get<std::string>());
    return body;
}

// The code a refusal page names ("" when the reply is not one).
std::string refusalCode(const HttpReply& reply)
{
    const std::size_t at = reply.body.find("Code: <code>");
    if (at == std::string::npos) return {};
    const std::size_t start = at + 12;
    return reply.body.substr(start, reply.body.find('<', start) - start);
}

class LtiPlatformPeer : public ::testing::Test {
protected:
    static void SetUpTestSuite()
    {
        serverPort = tlmhub::test::freeLoopbackPort();
        platform = new TemporaryLtiPlatform(serverUrl());
        const auto dir = tlmhub::test::freshTempDir("lti-platform-peer");
        keyFile = newToolKey(dir.parent_path() / "lti-platform-peer-tool-key.pem");
        const auto webRoot = dir.parent_path() / "lti-platform-peer-web";
        std::filesystem::create_directories(webRoot);
        std::ofstream(webRoot / "index.html") << "<!doctype html><title>tlmhub</title>";
        server = new ServerProcess(dir, {"--listen", "127.0.0.1:" + std::to_string(serverPort), "--public-url", serverUrl(),
                                         "--lti-key-file", keyFile.string(), "--lti-ca-file", platform->caFile().string(),
                                         "--web-root", webRoot.string()});
        HttpClient admin(server->port());
        admin.login("admin", tlmhub::test::kAdminPassword);
        const HttpReply registered = admin.post("/api/v1/admin/lti/platforms", platform->registration());
        if (registered.status != 201) throw std::runtime_error("cannot register the platform: " + registered.body);
        platformId = nlohmann::json::parse(registered.body).at("id").get<std::int64_t>();
    }
    static void TearDownTestSuite()
    {
        delete server;
        server = nullptr;
        delete platform;
        platform = nullptr;
    }

    static std::string serverUrl() { return "http://127.0.0.1:" + std::to_string(serverPort); }

    // The platform's login at the tool, in `browser` (which keeps the tool's cookie): the reply.
    static HttpReply loginAt(HttpClient& browser, const std::string& loginUrl)
    {
        const HttpReply reply = browser.get(loginUrl.substr(serverUrl().size()));
        if (reply.status == 302) {
            const std::string cookie = reply.headers.at("Set-Cookie");
            browser.addHeader("Cookie", cookie.substr(0, cookie.find(';')));
        }
        return reply;
    }
    // A launch staged at the platform (`launch`: /control/launch's body) taken by `browser` to
    // the tool's answer to the launch's form post.
    static HttpReply launch(HttpClient& browser, const nlohmann::json& staged)
    {
        const std::string loginUrl = platform->control("/control/launch", staged).at("loginUrl").get<std::string>();
        const HttpReply login = loginAt(browser, loginUrl);
        if (login.status != 302) throw std::runtime_error("login: " + std::to_string(login.status) + " " + login.body);
        const nlohmann::json form = platform->authenticate(login.headers.at("Location"));
        return browser.request(http::verb::post, "/api/v1/lti/launch", formBody(form), "application/x-www-form-urlencoded");
    }
    // A launch that must succeed: the browser's login afterwards, and the app page's route.
    static std::string launchAndSignIn(HttpClient& browser, const nlohmann::json& staged)
    {
        const HttpReply launched = launch(browser, staged);
        if (launched.status != 303)
            throw std::runtime_error("launch: " + std::to_string(launched.status) + " " + launched.body + "\n" +
                                     server->output());
        const std::string location = launched.headers.at("Location");
        const std::string prefix = serverUrl() + "/api/v1/lti/app#/signed-in/";
        if (!location.starts_with(prefix)) throw std::runtime_error("launch went to " + location);
        const std::string rest = location.substr(prefix.size());
        const HttpReply collected = browser.post("/api/v1/auth/oidc/collect", {{"key", rest.substr(0, rest.find('/'))}});
        if (collected.status != 200) throw std::runtime_error("collect: " + collected.body);
        browser.setToken(nlohmann::json::parse(collected.body).at("token").get<std::string>());
        return rest.find('/') == std::string::npos ? std::string{} : rest.substr(rest.find('/'));
    }
    // The teacher's placement of an assignment from a deep-linking launch: what the platform placed.
    static nlohmann::json placeAt(HttpClient& teacher, const std::string& key, std::int64_t assignmentId)
    {
        const HttpReply answer = teacher.post("/api/v1/lti/deep-links/" + key, {{"assignment_id", assignmentId}});
        if (answer.status != 200) throw std::runtime_error("place: " + answer.body);
        const auto signed_ = nlohmann::json::parse(answer.body);
        return platform->deepLinkReturn(signed_.at("return_url").get<std::string>(), signed_.at("jwt").get<std::string>());
    }
    // Polls the teacher's view of the assignment's scores until `done` holds (the outbox works
    // on its own thread); the last list.
    static nlohmann::json scoresUntil(HttpClient& teacher, std::int64_t assignmentId,
                                      const std::function<bool(const nlohmann::json&)>& done)
    {
        nlohmann::json scores;
        for (int i = 0; i < 600; ++i) {
            scores = nlohmann::json::parse(teacher.get("/api/v1/assignments/" + std::to_string(assignmentId) + "/lti-scores").body)
                         .at("scores");
            if (done(scores)) break;
            std::this_thread::sleep_for(std::chrono::milliseconds(100));
        }
        return scores;
    }
    static nlohmann::json person(const std::string& sub, const std::string& name, const std::string& role)
    {
        return {{"sub", sub}, {"name", name}, {"email", sub + "@uni.example"}, {"roles", {role}}};
    }

    static TemporaryLtiPlatform* platform;
    static ServerProcess* server;
    static unsigned short serverPort;
    static std::filesystem::path keyFile;
    static std::int64_t platformId;
};
TemporaryLtiPlatform* LtiPlatformPeer::platform = nullptr;
ServerProcess* LtiPlatformPeer::server = nullptr;
unsigned short LtiPlatformPeer::serverPort = 0;
std::filesystem::path LtiPlatformPeer::keyFile;
std::int64_t LtiPlatformPeer::platformId = 0;

} // namespace

TEST_F(LtiPlatformPeer, ATeachersFirstLaunchMakesTheCourseClassAndAStudentsLaunchJoinsIt)
{
    const nlohmann::json course = {{"id", "hydraulics-2026"}, {"title", "Hydraulics 2026"}};
    HttpClient early(server->port());
    const HttpReply tooEarly = launch(early, {{"user", person("s-early", "Early Student", "Learner")}, {"context", course}});
    EXPECT_EQ(tooEarly.status, 400);
    EXPECT_EQ(refusalCode(tooEarly), "course_not_ready") << tooEarly.body;

    HttpClient teacher(server->port());
    const std::string teacherRoute =
        launchAndSignIn(teacher, {{"user", person("t-1", "Grace Hopper", "Instructor")}, {"context", course}});
    ASSERT_TRUE(teacherRoute.starts_with("/class/")) << teacherRoute;
    const std::string classId = teacherRoute.substr(7);
    const HttpReply meReply = teacher.get("/api/v1/auth/me");
    ASSERT_EQ(meReply.status, 200) << meReply.body;
    const auto me = nlohmann::json::parse(meReply.body);
    EXPECT_EQ(me.at("username"), "Grace_Hopper") << "named after the launch's name, made a fine account name";
    EXPECT_EQ(me.at("role"), "user");
    const HttpReply classInfo = teacher.get("/api/v1/classes/" + classId);
    ASSERT_EQ(classInfo.status, 200) << classInfo.body;
    EXPECT_EQ(nlohmann::json::parse(classInfo.body).at("name"), "Hydraulics 2026");

    HttpClient student(server->port());
    EXPECT_EQ(launchAndSignIn(student, {{"user", person("s-1", "Ada Lovelace", "Learner")}, {"context", course}}),
              teacherRoute)
        << "the same course's class";
    HttpClient again(server->port());
    launchAndSignIn(again, {{"user", person("t-1", "Grace Hopper", "Instructor")}, {"context", course}});
    EXPECT_EQ(nlohmann::json::parse(again.get("/api/v1/auth/me").body).at("id"), me.at("id"))
        << "a second launch signs in to the same account";

    const auto members = nlohmann::json::parse(teacher.get("/api/v1/classes/" + classId).body).at("members");
    std::map<std::string, std::string> roles;
    for (const auto& member : members) roles[member.at("username").get<std::string>()] = member.at("role").get<std::string>();
    EXPECT_EQ(roles, (std::map<std::string, std::string>{{"Grace_Hopper", "teacher"}, {"Ada_Lovelace", "student"}}));
    const HttpReply asStudent = student.get("/api/v1/classes/" + classId);
    ASSERT_EQ(asStudent.status, 200) << "a member";
    EXPECT_FALSE(nlohmann::json::parse(asStudent.body).contains("members")) << "a student, not staff";

    HttpClient assistant(server->port());
    launchAndSignIn(assistant,
                    {{"user", person("ta-1", "Alan Turing",
                                     "http://purl.imsglobal.org/vocab/lis/v2/membership/Instructor#TeachingAssistant")},
                     {"context", course}});
    const auto withAssistant = nlohmann::json::parse(teacher.get("/api/v1/classes/" + classId).body).at("members");
    EXPECT_TRUE(std::any_of(withAssistant.begin(), withAssistant.end(), [](const nlohmann::json& m) {
        return m.at("username") == "Alan_Turing" && m.at("role") == "assistant";
    }));
}

// Before any launch with an unknown key (the broken ones below): those make the tool's one
// refetch of the minute, and a rotation right after one waits for the next minute.
TEST_F(LtiPlatformPeer, APlatformsRotatedKeyIsFetchedForItsNextLaunch)
{
    const nlohmann::json staged = {{"user", person("t-3", "Edsger Dijkstra", "Instructor")},
                                   {"context", {{"id", "rotation"}, {"title", "Rotation"}}}};
    HttpClient before(server->port());
    launchAndSignIn(before, staged);
    platform->control("/control/rotate-key", nlohmann::json::object());
    HttpClient after(server->port());
    EXPECT_NO_THROW(launchAndSignIn(after, staged)) << "signed with a key the tool had not fetched yet";
}

// One claim or the signature broken on purpose by the platform: the launch is refused with the
// check's code, and nobody is signed in.
TEST_F(LtiPlatformPeer, ALaunchBrokenInOneWayIsRefusedWithThatChecksCode)
{
    struct BrokenLaunch {
        const char* what;
        nlohmann::json tamper;
        const char* code;
    };
    const BrokenLaunch broken[] = {
        {"another audience", {{"claims", {{"aud", "another-tool"}}}}, "wrong_audience"},
        {"another issuer", {{"claims", {{"iss", "https://evil.example"}}}}, "wrong_issuer"},
        {"another audience beside ours", {{"claims", {{"aud", {"tlmhub-tool", "x"}}}}}, "wrong_audience"},
        {"another authorized party", {{"claims", {{"azp", "x"}}}}, "wrong_azp"},
        {"expired", {{"claims", {{"exp", "-600"}}}}, "expired"},
        {"issued in the future", {{"claims", {{"iat", "+3600"}}}}, "issued_in_future"},
        {"another nonce", {{"claims", {{"nonce", "replayed-nonce"}}}}, "wrong_nonce"},
        {"no subject", {{"claims", {{"sub", nullptr}}}}, "no_subject"},
        {"signed with an unknown key", {{"signWith", "unknownKey"}}, "bad_signature"},
        {"unsigned", {{"alg", "none"}}, "unsupported_algorithm"},
        {"a key not published", {{"kid", "missing"}}, "unknown_key"},
        {"another version", {{"claims", {{"version", "1.1.0"}}}}, "wrong_version"},
        {"another message type", {{"claims", {{"message_type", "LtiSubmissionReviewRequest"}}}}, "wrong_message_type"},
        {"an unknown deployment", {{"claims", {{"deployment_id", "deployment-2"}}}}, "unknown_deployment"},
        {"no roles", {{"claims", {{"roles", nullptr}}}}, "no_roles"},
        {"no resource link", {{"claims", {{"resource_link", nullptr}}}}, "no_resource_link"},
        {"a target elsewhere", {{"claims", {{"target_link_uri", "https://evil.example/x"}}}}, "wrong_target"},
        {"another state", {{"state", "made-up-state"}}, "launch_expired"},
    };
    for (const BrokenLaunch& launchBroken : broken) {
        SCOPED_TRACE(launchBroken.what);
        HttpClient browser(server->port());
        const HttpReply refused = launch(browser, {{"user", person("s-x", "Mallory", "Learner")},
                                                   {"context", {{"id", "checks"}, {"title", "Checks"}}},
                                                   {"tamper", launchBroken.tamper}});
        EXPECT_EQ(refused.status, 400) << refused.body;
        EXPECT_EQ(refusalCode(refused), launchBroken.code) << refused.body;
        EXPECT_EQ(refused.headers.count("Location"), 0U);
    }
}

TEST_F(LtiPlatformPeer, ALaunchIsTakenOnceAndOnlyInTheBrowserItsLoginCameThrough)
{
    const nlohmann::json staged = {{"user", person("t-2", "Barbara Liskov", "Instructor")},
                                   {"context", {{"id", "once"}, {"title", "Once"}}}};
    HttpClient browser(server->port());
    const std::string loginUrl = platform->control("/control/launch", staged).at("loginUrl").get<std::string>();
    const HttpReply login = loginAt(browser, loginUrl);
    ASSERT_EQ(login.status, 302) << login.body;
    const std::string cookie = login.headers.at("Set-Cookie");
    EXPECT_NE(cookie.find("HttpOnly"), std::string::npos);
    EXPECT_NE(cookie.find("SameSite=None"), std::string::npos) << "sent with the platform's cross-site form post";
    EXPECT_NE(cookie.find("Secure"), std::string::npos);
    EXPECT_NE(cookie.find("Path=/api/v1/lti"), std::string::npos);
    EXPECT_NE(cookie.find("Partitioned"), std::string::npos) << "kept inside the platform's frame (CHIPS)";
    const std::string authentication = login.headers.at("Location");
    ASSERT_TRUE(authentication.starts_with(platform->issuer() + "/auth?")) << authentication;
    const auto query = tlmhub::server::parseRequestTarget(authentication.substr(platform->issuer().size())).query;
    EXPECT_EQ(query.at("scope"), "openid");
    EXPECT_EQ(query.at("response_type"), "id_token");
    EXPECT_EQ(query.at("response_mode"), "form_post");
    EXPECT_EQ(query.at("prompt"), "none");
    EXPECT_EQ(query.at("client_id"), TemporaryLtiPlatform::kClientId);
    EXPECT_EQ(query.at("redirect_uri"), serverUrl() + "/api/v1/lti/launch");
    EXPECT_GE(query.at("state").size(), 43U);
    EXPECT_GE(query.at("nonce").size(), 43U);
    const nlohmann::json form = platform->authenticate(authentication);

    HttpClient otherBrowser(server->port());   // someone else's launch pushed into this browser
    otherBrowser.addHeader("Cookie", "tlmhub_lti=not-the-login-s");
    const HttpReply pushed =
        otherBrowser.request(http::verb::post, "/api/v1/lti/launch", formBody(form), "application/x-www-form-urlencoded");
    EXPECT_EQ(refusalCode(pushed), "wrong_browser");
    const HttpReply afterPush =
        browser.request(http::verb::post, "/api/v1/lti/launch", formBody(form), "application/x-www-form-urlencoded");
    EXPECT_EQ(refusalCode(afterPush), "launch_expired") << "the state was used by the refused attempt";

    HttpClient fresh(server->port());
    const std::string loginUrl2 = platform->control("/control/launch", staged).at("loginUrl").get<std::string>();
    const HttpReply login2 = loginAt(fresh, loginUrl2);
    const nlohmann::json form2 = platform->authenticate(login2.headers.at("Location"));
    EXPECT_EQ(fresh.request(http::verb::post, "/api/v1/lti/launch", formBody(form2), "application/x-www-form-urlencoded").status,
              303);
    const HttpReply replayed =
        fresh.request(http::verb::post, "/api/v1/lti/launch", formBody(form2), "application/x-www-form-urlencoded");
    EXPECT_EQ(refusalCode(replayed), "launch_expired") << "a replayed launch (its nonce used)";
}

TEST_F(LtiPlatformPeer, ALoginFromAnUnknownPlatformOrForATargetElsewhereGoesNowhere)
{
    HttpClient browser(server->port());
    const auto target = tlmhub::net::percentEncode(serverUrl() + "/api/v1/lti/launch");
    const HttpReply unknown = browser.get("/api/v1/lti/login?iss=" + tlmhub::net::percentEncode("https://evil.example") +
                                          "&login_hint=1&target_link_uri=" + target);
    EXPECT_EQ(unknown.status, 400);
    EXPECT_EQ(refusalCode(unknown), "unknown_platform");
    const auto iss = tlmhub::net::percentEncode(platform->issuer());
    const HttpReply elsewhere = browser.get("/api/v1/lti/login?iss=" + iss + "&login_hint=1&target_link_uri=" +
                                            tlmhub::net::percentEncode("https://evil.example/"));
    EXPECT_EQ(refusalCode(elsewhere), "wrong_target");
    const HttpReply otherDeployment = browser.get("/api/v1/lti/login?iss=" + iss + "&login_hint=1&target_link_uri=" +
                                                  target + "&lti_deployment_id=deployment-9");
    EXPECT_EQ(refusalCode(otherDeployment), "unknown_deployment");
    const HttpReply posted = browser.request(http::verb::post, "/api/v1/lti/login",
                                             "iss=" + iss + "&login_hint=7&target_link_uri=" + target +
                                                 "&client_id=" + TemporaryLtiPlatform::kClientId,
                                             "application/x-www-form-urlencoded");
    EXPECT_EQ(posted.status, 302) << "a login may be a form post too: " << posted.body;
}

TEST_F(LtiPlatformPeer, TheToolPublishesTheKeyItSignsWith)
{
    HttpClient anyone(server->port());
    const HttpReply published = anyone.get("/api/v1/lti/jwks");
    ASSERT_EQ(published.status, 200);
    std::string error;
    const auto keys = tlmhub::server::JsonWebKeySet::parse(nlohmann::json::parse(published.body), error);
    ASSERT_TRUE(keys) << error;
    const tlmhub::server::ToolKeys tool({keyFile.string()});
    const std::string jwt = tool.sign({{"iss", "tlmhub-tool"}, {"aud", "https://platform.example"}});
    const std::size_t dot = jwt.rfind('.');
    const auto* key = keys->find(tool.signingKeyId(), "RS256");
    ASSERT_NE(key, nullptr) << "published under the id it signs with";
    EXPECT_TRUE(tlmhub::server::verifyJwsSignature(*key, "RS256", std::string_view(jwt).substr(0, dot),
                                                   *tlmhub::server::decodeBase64Url(jwt.substr(dot + 1))));
    EXPECT_FALSE(tlmhub::server::verifyJwsSignature(*key, "RS256", "tampered." + jwt.substr(0, dot),
                                                    *tlmhub::server::decodeBase64Url(jwt.substr(dot + 1))));
}

TEST_F(LtiPlatformPeer, TheLaunchPageMayBeFramedByRegisteredPlatformsOnly)
{
    HttpClient anyone(server->port());
    const HttpReply page = anyone.get("/api/v1/lti/app");
    ASSERT_EQ(page.status, 200) << page.body;
    EXPECT_EQ(page.body, "<!doctype html><title>tlmhub</title>") << "the app's page";
    const std::string policy = page.headers.at("Content-Security-Policy");
    EXPECT_NE(policy.find("frame-ancestors 'self' " + platform->issuer()), std::string::npos) << policy;
    EXPECT_EQ(policy.find("frame-ancestors", policy.find("frame-ancestors") + 1), std::string::npos) << "one directive";
    const HttpReply refused = anyone.request(http::verb::post, "/api/v1/lti/launch", "state=x&id_token=y",
                                             "application/x-www-form-urlencoded");
    EXPECT_EQ(refusalCode(refused), "launch_expired");
    EXPECT_NE(refused.headers.at("Content-Security-Policy").find("frame-ancestors 'self' " + platform->issuer()),
              std::string::npos)
        << "a refused launch is read inside the platform's frame too";
    const HttpReply app = anyone.get("/");
    EXPECT_NE(app.headers.at("Content-Security-Policy").find("frame-ancestors 'self'"), std::string::npos);
    EXPECT_EQ(app.headers.at("Content-Security-Policy").find(platform->issuer()), std::string::npos)
        << "every other page: this server only";
}

TEST_F(LtiPlatformPeer, OnlyAdministratorsManageThePlatforms)
{
    HttpClient admin(server->port());
    admin.login("admin", tlmhub::test::kAdminPassword);
    const auto list = nlohmann::json::parse(admin.get("/api/v1/admin/lti/platforms").body);
    EXPECT_EQ(list.at("tool").at("login_url"), serverUrl() + "/api/v1/lti/login");
    EXPECT_EQ(list.at("tool").at("jwks_url"), serverUrl() + "/api/v1/lti/jwks");
    EXPECT_TRUE(list.at("tool").at("enabled").get<bool>());
    EXPECT_EQ(admin.post("/api/v1/admin/lti/platforms", platform->registration()).status, 409) << "registered already";

    nlohmann::json canvas = platform->registration();
    canvas["name"] = "Canvas";
    canvas["issuer"] = "https://canvas.instructure.com";
    canvas["client_id"] = "10000000000001";
    const HttpReply created = admin.post("/api/v1/admin/lti/platforms", canvas);
    ASSERT_EQ(created.status, 201) << created.body;
    const std::string path = "/api/v1/admin/lti/platforms/" + std::to_string(nlohmann::json::parse(created.body).at("id").get<int>());
    canvas["jwks_url"] = "http://canvas.instructure.com/keys";
    EXPECT_EQ(admin.request(http::verb::put, path, canvas.dump()).status, 400) << "https only";
    canvas["jwks_url"] = "https://sso.canvaslms.com/api/lti/security/jwks";
    canvas["deployment_ids"] = {"1:abc", "2:def"};
    const HttpReply updated = admin.request(http::verb::put, path, canvas.dump());
    ASSERT_EQ(updated.status, 200) << updated.body;
    EXPECT_EQ(nlohmann::json::parse(updated.body).at("deployment_ids"), nlohmann::json::array({"1:abc", "2:def"}));

    admin.post("/api/v1/users", {{"username", "lti-nobody"}, {"password", "a-long-password"}, {"role", "teacher"}});
    HttpClient teacher(server->port());
    teacher.login("lti-nobody", "a-long-password");
    EXPECT_EQ(teacher.get("/api/v1/admin/lti/platforms").status, 403);
    EXPECT_EQ(teacher.get(path).status, 403);
    EXPECT_EQ(teacher.request(http::verb::delete_, path).status, 403);
    EXPECT_EQ(teacher.post("/api/v1/admin/lti/platforms", canvas).status, 403);
    EXPECT_EQ(HttpClient(server->port()).get("/api/v1/admin/lti/platforms").status, 401);

    EXPECT_EQ(admin.request(http::verb::delete_, path).status, 204);
    EXPECT_EQ(admin.get(path).status, 404);
    EXPECT_EQ(nlohmann::json::parse(admin.get("/api/v1/admin/lti/platforms").body).at("platforms").size(), 1U);
}

TEST_F(LtiPlatformPeer, ATeacherPlacesAnAssignmentAndTheLinkOpensItAndItsScoresReachTheGradeBook)
{
    const nlohmann::json course = {{"id", "placement"}, {"title", "Placement"}};
    HttpClient teacher(server->port());
    const std::string route = launchAndSignIn(
        teacher, {{"user", person("t-9", "Tina Teacher", "Instructor")}, {"context", course}, {"messageType", "LtiDeepLinkingRequest"}});
    ASSERT_TRUE(route.starts_with("/place/")) << route;
    const std::string key = route.substr(7);
    const auto waiting = nlohmann::json::parse(teacher.get("/api/v1/lti/deep-links/" + key).body);
    EXPECT_EQ(waiting.at("platform"), "Test platform");
    const std::int64_t classId = waiting.at("class_id").get<std::int64_t>();

    const std::int64_t templateId = tlmhub::test::uploadModel(teacher, tlmhub::test::kPositionServo, "servo");
    const HttpReply created = teacher.post("/api/v1/classes/" + std::to_string(classId) + "/assignments",
                                           {{"title", "Tune the servo"}, {"template_model_id", templateId}});
    ASSERT_EQ(created.status, 201) << created.body;
    const std::int64_t assignmentId = nlohmann::json::parse(created.body).at("id").get<std::int64_t>();
    const std::string assignmentPath = "/api/v1/assignments/" + std::to_string(assignmentId);
    ASSERT_EQ(teacher.request(http::verb::put, assignmentPath + "/checks",
                              nlohmann::json{{"checks",
                                              {{{"name", "Ends near the target"}, {"points", 4},
                                                {"definition", {{"kind", "scalar"}, {"variable", "Position_Sensor#out#Value"},
                                                                {"measure", "final"}, {"min", -1}, {"max", 1}}}}}}}
                                  .dump())
                  .status,
              200);

    HttpClient stranger(server->port());
    stranger.login("admin", tlmhub::test::kAdminPassword);
    EXPECT_EQ(stranger.get("/api/v1/lti/deep-links/" + key).status, 404) << "another user's placement";
    EXPECT_EQ(stranger.post("/api/v1/lti/deep-links/" + key, {{"assignment_id", assignmentId}}).status, 404);
    const nlohmann::json placed = placeAt(teacher, key, assignmentId);
    ASSERT_EQ(placed.at("placed").size(), 1U) << placed;
    const nlohmann::json link = placed.at("placed")[0];
    EXPECT_EQ(link.at("url"), serverUrl() + "/api/v1/lti/launch");
    EXPECT_EQ(link.at("title"), "Tune the servo");
    EXPECT_EQ(link.at("custom").at("assignment"), std::to_string(assignmentId));
    EXPECT_FALSE(link.at("lineitem").is_null()) << "the platform made the line item the answer asked for";
    EXPECT_EQ(teacher.post("/api/v1/lti/deep-links/" + key, {{"assignment_id", assignmentId}}).status, 404) << "once";

    HttpClient student(server->port());
    const nlohmann::json studentLaunch = {{"user", person("s-9", "Sam Student", "Learner")},
                                          {"context", course},
                                          {"resourceLink", {{"id", link.at("resourceLinkId")}}}};
    EXPECT_EQ(launchAndSignIn(student, studentLaunch), "/assignment/" + std::to_string(assignmentId))
        << "the placed link opens the assignment";
    ASSERT_EQ(student.post(assignmentPath + "/open", nlohmann::json::object()).status / 100, 2);
    const HttpReply handedIn = student.post(assignmentPath + "/handin", nlohmann::json::object());
    ASSERT_EQ(handedIn.status, 201) << handedIn.body;
    const double score = nlohmann::json::parse(handedIn.body).at("score").get<double>();

    const auto delivered = scoresUntil(teacher, assignmentId, [](const nlohmann::json& list) {
        return list.size() == 1 && list[0].at("state") == "delivered";
    });
    ASSERT_EQ(delivered.size(), 1U) << delivered;
    EXPECT_EQ(delivered[0].at("state"), "delivered") << delivered;
    EXPECT_EQ(delivered[0].at("user").at("username"), "Sam_Student");
    EXPECT_EQ(delivered[0].at("platform"), "Test platform");
    const auto received = platform->control("/control/scores");
    ASSERT_EQ(received.size(), 1U) << received;
    EXPECT_EQ(received[0].at("lineitem"), link.at("lineitem"));
    EXPECT_EQ(received[0].at("score").at("userId"), "s-9") << "the person as the platform knows them";
    EXPECT_EQ(received[0].at("score").at("scoreGiven"), score);
    EXPECT_EQ(received[0].at("score").at("scoreMaximum"), 4);
    EXPECT_EQ(received[0].at("score").at("gradingProgress"), "FullyGraded");
    EXPECT_EQ(student.get(assignmentPath + "/lti-scores").status, 403) << "for the class's staff";

    // The platform down: the teacher's grade waits in the outbox, then goes once it is back.
    platform->control("/control/down", nlohmann::json::object());
    const std::int64_t handInId = nlohmann::json::parse(handedIn.body).at("id").get<std::int64_t>();
    ASSERT_EQ(teacher.request(http::verb::put, "/api/v1/handins/" + std::to_string(handInId) + "/grade", R"({"grade": 3.5})").status,
              200);
    const auto waitingScores = scoresUntil(teacher, assignmentId, [](const nlohmann::json& list) {
        return !list.empty() && list[0].at("attempts").get<int>() >= 1 && !list[0].at("last_error").get<std::string>().empty();
    });
    EXPECT_EQ(waitingScores[0].at("state"), "pending");
    EXPECT_NE(waitingScores[0].at("last_error").get<std::string>().find("503"), std::string::npos) << waitingScores[0];
    platform->control("/control/up", nlohmann::json::object());
    const auto afterUp = scoresUntil(teacher, assignmentId, [](const nlohmann::json& list) {
        return !list.empty() && list[0].at("state") == "delivered";
    });
    EXPECT_EQ(afterUp[0].at("state"), "delivered") << afterUp[0];
    EXPECT_GE(afterUp[0].at("attempts").get<int>(), 2);
    const auto all = platform->control("/control/scores");
    ASSERT_EQ(all.size(), 2U) << all;
    EXPECT_EQ(all[1].at("score").at("scoreGiven"), 3.5) << "the teacher's grade";
    const auto results = platform->control("/control/lineitems");
    EXPECT_NE(results.dump().find("3.5"), std::string::npos) << "read back from the line item: " << results;
}

TEST_F(LtiPlatformPeer, OnlyATeachersDeepLinkingLaunchPlaces)
{
    HttpClient student(server->port());
    const HttpReply refused = launch(student, {{"user", person("s-10", "Sue Student", "Learner")},
                                               {"context", {{"id", "placement"}, {"title", "Placement"}}},
                                               {"messageType", "LtiDeepLinkingRequest"}});
    EXPECT_EQ(refusalCode(refused), "not_instructor") << refused.body;
}
