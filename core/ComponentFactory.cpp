#include "core/ComponentFactory.h"

namespace tlmhub {

ComponentFactory& ComponentFactory::instance()
{
    static ComponentFactory factory;
    return factory;
}

bool ComponentFactory::registerType(const std::string& typeName, const std::string& domain,
                                    ComponentCreator create)
{
    return mTypes.emplace(typeName, ComponentTypeInfo{typeName, domain, create}).second;
}

bool ComponentFactory::hasType(const std::string& typeName) const
{
    return mTypes.count(typeName) != 0;
}

std::unique_ptr<Component> ComponentFactory::create(const std::string& typeName) const
{
    auto it = mTypes.find(typeName);
    if (it == mTypes.end()) return nullptr;
    std::unique_ptr<Component> c = it->second.create();
    c->setTypeName(typeName);
    c->setNameRaw(typeName);
    c->libraryDomain = it->second.domain;
    c->configure();
    return c;
}

std::vector<std::string> ComponentFactory::typeNames() const
{
    std::vector<std::string> names;
    names.reserve(mTypes.size());
    for (const auto& [name, info] : mTypes) names.push_back(name);
    return names;
}

const ComponentTypeInfo* ComponentFactory::info(const std::string& typeName) const
{
    auto it = mTypes.find(typeName);
    return it == mTypes.end() ? nullptr : &it->second;
}

} // namespace tlmhub
