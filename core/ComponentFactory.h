#pragma once
// Component factory: makes components from a type-name string (core.md §9).
// Each component type registers itself in its own .cpp with TLMHUB_REGISTER_COMPONENT.
#include "core/Component.h"
#include "core/StepBatches.h"

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace tlmhub {

using ComponentCreator = std::unique_ptr<Component> (*)();

struct ComponentTypeInfo {
    std::string typeName;
    std::string domain;   // palette group: Hydraulic, Mechanic, Signal, Electric, Pneumatic, Aero, Other
    ComponentCreator create = nullptr;
};

class ComponentFactory {
public:
    static ComponentFactory& instance();

    bool registerType(const std::string& typeName, const std::string& domain,
                      ComponentCreator create);
    bool hasType(const std::string& typeName) const;
    // A configured component (ports and parameters registered), named after its type;
    // null if the type is unknown.
    std::unique_ptr<Component> create(const std::string& typeName) const;
    std::vector<std::string> typeNames() const;
    const ComponentTypeInfo* info(const std::string& typeName) const;

private:
    std::map<std::string, ComponentTypeInfo> mTypes;
};

} // namespace tlmhub

#define TLMHUB_REGISTER_COMPONENT(Type, Domain)                                              \
    namespace {                                                                              \
    [[maybe_unused]] const bool tlmhubRegistered_##Type =                                    \
        ::tlmhub::ComponentFactory::instance().registerType(                                 \
            #Type, Domain, []() -> std::unique_ptr<::tlmhub::Component> {                    \
                auto component = std::make_unique<Type>();                                   \
                component->setBatchStepper(&::tlmhub::stepBatchOf<Type>);                    \
                return component;                                                            \
            });                                                                              \
    }
