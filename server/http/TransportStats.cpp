#include "server/http/TransportStats.h"

namespace tlmhub::server {

TransportStats& TransportStats::instance()
{
    static TransportStats stats;
    return stats;
}

} // namespace tlmhub::server
