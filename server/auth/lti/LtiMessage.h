#pragma once
// What an LTI 1.3 launch says, read from its ID token once the token itself checked (signature,
// issuer, audience, times, nonce: IdTokenVerifier), with the checks LTI 1.3 Core (§5.1.2,
// §5.3, §5.4) and Deep Linking 2.0 (§4.4) add: the version, a message type this tool takes,
// a deployment registered for the platform, the roles claim, a resource link or deep-linking
// settings by type, and a target on this server. Each failure has a stable code.
#include <nlohmann/json.hpp>

#include <string>
#include <variant>
#include <vector>

namespace tlmhub::server {

inline constexpr const char* kLtiResourceLinkRequest = "LtiResourceLinkRequest";
inline constexpr const char* kLtiDeepLinkingRequest = "LtiDeepLinkingRequest";

struct LtiMessage {
    std::string messageType;                    // kLtiResourceLinkRequest or kLtiDeepLinkingRequest
    std::string deploymentId;
    std::string subject;                        // `sub`: with the issuer, who the person is
    std::string name;                           // what to name a new account after
    std::string classRole;                      // teacher, assistant or student in the course; "" for none
    std::string contextId, contextTitle;        // the course; id "" when the launch has none
    std::string resourceLinkId, resourceLinkTitle;
    std::string targetLinkUri;
    nlohmann::json custom = nlohmann::json::object();   // the link's custom parameters (strings)
    std::string lineItem;                       // grade services: the link's line item, else ""
    std::vector<std::string> gradeScopes;       // grade services: the scopes granted
    std::string deepLinkReturnUrl, deepLinkData;   // deep linking: where the answer goes, echoed data
};

struct LtiMessageError {
    // wrong_version, wrong_message_type, unknown_deployment, no_roles, no_resource_link,
    // no_deep_linking_settings, wrong_target
    std::string code;
    std::string message;
};

// `claims`: a checked ID token's. `deploymentIds`: the platform's registered ones. `toolUrl`:
// this server's public address; the target must be on it.
std::variant<LtiMessage, LtiMessageError> readLtiMessage(const nlohmann::json& claims, const std::string& subject,
                                                         const std::vector<std::string>& deploymentIds,
                                                         const std::string& toolUrl);

// The class role LTI roles give in the course: TeachingAssistant an assistant, Instructor,
// Administrator or ContentDeveloper of the course a teacher, Learner a student; "" for the rest
// (a Mentor, or institution roles only). Full IRIs and the deprecated short names both count.
std::string classRoleOf(const nlohmann::json& roles);

} // namespace tlmhub::server
