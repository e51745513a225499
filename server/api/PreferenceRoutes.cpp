// GET /preferences, PUT /preferences: each account's own settings (the display unit chosen per
// quantity), kept on the server so they follow the user from browser to browser.
#include "server/api/ApiSupport.h"

namespace tlmhub::server {

namespace {

constexpr std::size_t kMaxUnits = 100;
constexpr std::size_t kMaxNameLength = 40;

// What was stored, as the protocol has it; a row from before a field existed gets its default.
protocol::Preferences storedPreferences(const std::string& text)
{
    protocol::Preferences preferences;
    const nlohmann::json stored = nlohmann::json::parse(text, nullptr, false);
    if (stored.is_object() && stored.contains("units") && stored.at("units").is_object())
        for (const auto& [quantity, unit] : stored.at("units").items())
            if (unit.is_string()) preferences.units[quantity] = unit.get<std::string>();
    return preferences;
}

Response getPreferences(Services& s, Call& call)
{
    const auto stored = s.users.preferences(call.who().id);
    if (!stored) return apiError(http::status::not_found, "not_found", "no such user");
    return jsonResponse(http::status::ok, storedPreferences(*stored));
}

Response putPreferences(Services& s, Call& call)
{
    protocol::Preferences body;
    Response error;
    if (!readBody(call, "Preferences", body, error)) return error;
    if (body.units.size() > kMaxUnits)
        return apiError(http::status::bad_request, "bad_request",
                        "units: at most " + std::to_string(kMaxUnits) + " quantities, got " +
                            std::to_string(body.units.size()));
    for (const auto& [quantity, unit] : body.units)
        if (quantity.empty() || quantity.size() > kMaxNameLength)
            return apiError(http::status::bad_request, "bad_request",
                            "units: a quantity's name has 1 to " + std::to_string(kMaxNameLength) + " characters");
    const nlohmann::json stored = body;
    if (!s.users.setPreferences(call.who().id, stored.dump()))
        return apiError(http::status::not_found, "not_found", "no such user");
    return jsonResponse(http::status::ok, stored);
}

} // namespace

void addPreferenceRoutes(std::vector<RouteSpec>& routes)
{
    routes.push_back({http::verb::get, "/preferences", true, getPreferences});
    routes.push_back({http::verb::put, "/preferences", true, putPreferences});
}

} // namespace tlmhub::server
