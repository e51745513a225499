#include "core/Catalogue.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

nlohmann::json componentCatalogue()
{
    nlohmann::json list = nlohmann::json::array();
    const ComponentFactory& factory = ComponentFactory::instance();
    for (const std::string& type : factory.typeNames()) {
        std::unique_ptr<Component> c = factory.create(type);
        if (!c) continue;
        nlohmann::json entry;
        entry["type"] = type;
        entry["kind"] = cqsKindName(c->kind());
        entry["domain"] = factory.info(type)->domain;
        nlohmann::json ports = nlohmann::json::array();
        for (Port* p : c->ports()) {
            ports.push_back({{"name", p->name()},
                             {"nodetype", std::string(nodeTypeInfo(p->nodeType()).typeName)},
                             {"porttype", portKindName(p->kind())},
                             {"required", p->required},
                             {"description", p->description}});
        }
        entry["ports"] = ports;
        nlohmann::json params = nlohmann::json::array();
        for (const auto& p : c->parameters().all()) {
            nlohmann::json jp = {{"name", p->name},
                                 {"default", p->defaultValue},
                                 {"type", parameterTypeName(p->type)},
                                 {"unit", p->unit},
                                 {"description", p->description}};
            if (!p->conditions.empty()) jp["choices"] = p->conditions;
            params.push_back(jp);
        }
        entry["parameters"] = params;
        list.push_back(entry);
    }
    return list;
}

} // namespace tlmhub
