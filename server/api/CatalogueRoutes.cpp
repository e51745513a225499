// GET /health, GET /openapi.json (no login needed), GET /components (the core's catalogue),
// GET /stats (administrators: transport gauges).
#include "server/api/ApiSupport.h"
#include "server/auth/AccessPolicy.h"

#include "server/http/TransportStats.h"
#include "server/protocol/EmbeddedProtocol.h"

#include "core/Catalogue.h"

namespace tlmhub::server {

namespace {

Response health(Services&, Call&)
{
    return jsonResponse(http::status::ok, protocol::HealthResponse{});
}

Response openapi(Services&, Call&)
{
    for (const EmbeddedFile& f : embeddedProtocolFiles())
        if (f.name == "openapi.json") return textResponse(http::status::ok, f.content, "application/json");
    return apiError(http::status::not_found, "not_found", "openapi.json was not built in");
}

Response components(Services&, Call&)
{
    // The catalogue only changes when component libraries load (at start-up), so it is
    // serialised once.
    static const std::string catalogue = componentCatalogue().dump();
    return textResponse(http::status::ok, catalogue, "application/json");
}

Response stats(Services&, Call& call)
{
    if (!isAdministrator(call.who()))
        return apiError(http::status::forbidden, "forbidden", "only administrators read the server's stats");
    const TransportStats& t = TransportStats::instance();
    return jsonResponse(http::status::ok,
                        protocol::ServerStats{
                            .websockets = t.webSockets.load(),
                            .websocketQueuedBytes = t.webSocketQueuedBytes.load(),
                            .websocketsClosedForBacklog = static_cast<std::int64_t>(t.webSocketsClosedForBacklog.load())});
}

} // namespace

void addCatalogueRoutes(std::vector<RouteSpec>& routes)
{
    routes.push_back({http::verb::get, "/health", false, health, RouteWork::Instant});
    routes.push_back({http::verb::get, "/openapi.json", false, openapi, RouteWork::Instant});
    routes.push_back({http::verb::get, "/components", true, components});
    routes.push_back({http::verb::get, "/stats", true, stats});
}

} // namespace tlmhub::server
