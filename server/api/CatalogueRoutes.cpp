// GET /health, GET /openapi.json (no login needed), GET /components (the core's catalogue).
#include "server/api/ApiSupport.h"

#include "server/protocol/EmbeddedProtocol.h"

#include "core/Catalogue.h"

namespace tlmhub::server {

namespace {

Response health(Services&, Call&)
{
    return jsonResponse(http::status::ok, {{"status", "ok"}});
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

} // namespace

void addCatalogueRoutes(std::vector<RouteSpec>& routes)
{
    routes.push_back({http::verb::get, "/health", false, health});
    routes.push_back({http::verb::get, "/openapi.json", false, openapi});
    routes.push_back({http::verb::get, "/components", true, components});
}

} // namespace tlmhub::server
