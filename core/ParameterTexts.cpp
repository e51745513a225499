#include "core/ParameterTexts.h"

#include "core/System.h"

namespace tlmhub {

namespace {

// `prefix` is "" for the root's components, "Sub$" inside subsystem Sub, and so on.
void collect(const System& system, const std::string& prefix, std::map<std::string, std::string>& out)
{
    for (const Component* c : system.componentsInOrder()) {
        const std::string owner = prefix + c->name();
        for (const auto& p : c->parameters().all()) out.emplace(owner + "." + p->name, p->value);
        if (c->isSystem()) collect(*static_cast<const System*>(c), owner + "$", out);
    }
}

} // namespace

std::map<std::string, std::string> parameterTexts(const System& root)
{
    std::map<std::string, std::string> out;
    for (const auto& p : root.parameters().all()) out.emplace(p->name, p->value);
    collect(root, "", out);
    return out;
}

} // namespace tlmhub
