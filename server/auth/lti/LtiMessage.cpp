#include "server/auth/lti/LtiMessage.h"

#include "server/auth/oidc/JsonMembers.h"
#include "server/store/LabStore.h"

#include <algorithm>

namespace tlmhub::server {

namespace {

constexpr const char* kLtiClaim = "https://purl.imsglobal.org/spec/lti/claim/";
constexpr const char* kDeepLinkingSettingsClaim = "https://purl.imsglobal.org/spec/lti-dl/claim/deep_linking_settings";
constexpr const char* kGradeEndpointClaim = "https://purl.imsglobal.org/spec/lti-ags/claim/endpoint";
constexpr const char* kMembershipRole = "http://purl.imsglobal.org/vocab/lis/v2/membership#";
constexpr const char* kTeachingAssistantRole = "http://purl.imsglobal.org/vocab/lis/v2/membership/Instructor#TeachingAssistant";

const nlohmann::json& ltiClaim(const nlohmann::json& claims, const std::string& name)
{
    static const nlohmann::json missing;
    const auto it = claims.find(kLtiClaim + name);
    return it == claims.end() ? missing : *it;
}

std::string ltiString(const nlohmann::json& claims, const std::string& name)
{
    const nlohmann::json& value = ltiClaim(claims, name);
    return value.is_string() ? value.get<std::string>() : std::string{};
}

LtiMessageError ltiRefusal(std::string code, std::string message)
{
    return {std::move(code), std::move(message)};
}

// A context role: its full IRI or its deprecated short name.
bool holdsRole(const nlohmann::json& roles, const std::string& name)
{
    return std::any_of(roles.begin(), roles.end(), [&](const nlohmann::json& role) {
        return role.is_string() && (role.get<std::string>() == kMembershipRole + name || role.get<std::string>() == name);
    });
}

} // namespace

std::string classRoleOf(const nlohmann::json& roles)
{
    if (!roles.is_array()) return {};
    if (holdsRole(roles, "TeachingAssistant") ||
        std::any_of(roles.begin(), roles.end(), [](const nlohmann::json& r) { return r == kTeachingAssistantRole; }))
        return kClassAssistant;
    for (const char* teaching : {"Instructor", "Administrator", "ContentDeveloper"})
        if (holdsRole(roles, teaching)) return kClassTeacher;
    if (holdsRole(roles, "Learner")) return kClassStudent;
    return {};
}

std::variant<LtiMessage, LtiMessageError> readLtiMessage(const nlohmann::json& claims, const std::string& subject,
                                                         const std::vector<std::string>& deploymentIds,
                                                         const std::string& toolUrl)
{
    if (ltiString(claims, "version") != "1.3.0")
        return ltiRefusal("wrong_version", "the launch is not LTI version 1.3.0");
    LtiMessage message;
    message.messageType = ltiString(claims, "message_type");
    if (message.messageType != kLtiResourceLinkRequest && message.messageType != kLtiDeepLinkingRequest)
        return ltiRefusal("wrong_message_type", "the launch's message type is not one this tool takes");
    message.deploymentId = ltiString(claims, "deployment_id");
    if (message.deploymentId.empty() ||
        std::find(deploymentIds.begin(), deploymentIds.end(), message.deploymentId) == deploymentIds.end())
        return ltiRefusal("unknown_deployment", "the launch's deployment is not registered for the platform");
    const nlohmann::json& roles = ltiClaim(claims, "roles");
    if (!roles.is_array()) return ltiRefusal("no_roles", "the launch has no roles claim");
    message.classRole = classRoleOf(roles);
    message.subject = subject;
    for (const char* claim : {"name", "given_name", "email"})
        if (message.name = stringMember(claims, claim); !message.name.empty()) break;
    if (message.name.empty()) message.name = "student";
    if (message.name.find('@') != std::string::npos) message.name.resize(message.name.find('@'));

    const nlohmann::json& context = ltiClaim(claims, "context");
    message.contextId = stringMember(context, "id");
    message.contextTitle = stringMember(context, "title");
    if (message.contextTitle.empty()) message.contextTitle = stringMember(context, "label");
    const nlohmann::json& custom = ltiClaim(claims, "custom");
    if (custom.is_object())
        for (const auto& [key, value] : custom.items())
            if (value.is_string()) message.custom[key] = value;

    message.targetLinkUri = ltiString(claims, "target_link_uri");
    if (message.messageType == kLtiResourceLinkRequest) {
        const nlohmann::json& link = ltiClaim(claims, "resource_link");
        message.resourceLinkId = stringMember(link, "id");
        message.resourceLinkTitle = stringMember(link, "title");
        if (message.resourceLinkId.empty()) return ltiRefusal("no_resource_link", "the launch has no resource link id");
        // Our own addresses only: a target elsewhere would make this server a relay to anywhere.
        if (!message.targetLinkUri.starts_with(toolUrl + "/"))
            return ltiRefusal("wrong_target", "the launch's target link is not on this server");
        const auto endpoint = claims.find(kGradeEndpointClaim);
        if (endpoint != claims.end() && endpoint->is_object()) {
            message.lineItem = stringMember(*endpoint, "lineitem");
            if (const auto scopes = endpoint->find("scope"); scopes != endpoint->end() && scopes->is_array())
                for (const nlohmann::json& scope : *scopes)
                    if (scope.is_string()) message.gradeScopes.push_back(scope.get<std::string>());
        }
    } else {
        const auto settings = claims.find(kDeepLinkingSettingsClaim);
        if (settings != claims.end() && settings->is_object()) {
            message.deepLinkReturnUrl = stringMember(*settings, "deep_link_return_url");
            message.deepLinkData = stringMember(*settings, "data");
        }
        if (!message.deepLinkReturnUrl.starts_with("https://"))
            return ltiRefusal("no_deep_linking_settings", "the deep-linking launch has no https return address");
    }
    return message;
}

} // namespace tlmhub::server
