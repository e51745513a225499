#include "server/store/ModelStore.h"

#include "server/auth/AccessPolicy.h"

namespace tlmhub::server {

std::vector<ModelSummary> ModelStore::listVisibleTo(const User& who)
{
    std::vector<ModelSummary> visible;
    for (ModelSummary& s : list())
        if (canRead(who, s.ownerId, s.isExample)) visible.push_back(std::move(s));
    return visible;
}

} // namespace tlmhub::server
