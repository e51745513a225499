#include "server/api/ApiSupport.h"

namespace tlmhub::server {

std::vector<RouteSpec> apiRoutes()
{
    std::vector<RouteSpec> routes;
    addCatalogueRoutes(routes);
    addAuthRoutes(routes);
    addOidcRoutes(routes);
    addLtiRoutes(routes);
    addUserRoutes(routes);
    addPreferenceRoutes(routes);
    addModelRoutes(routes);
    addFmuRoutes(routes);
    addJobRoutes(routes);
    addStudyRoutes(routes);
    addTokenRoutes(routes);
    addClassRoutes(routes);
    addAssignmentRoutes(routes);
    addHandInRoutes(routes);
    return routes;
}

} // namespace tlmhub::server
