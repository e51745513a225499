#include "core/SystemCopy.h"

#include "core/ComponentFactory.h"
#include "core/SystemConnections.h"

namespace tlmhub {

namespace {

// The steps follow core/hmf/HmfLoader.cpp's order (settings, system parameters, objects,
// system ports, connections, system parameters again, aliases), so that whatever depends on
// order (multiport sub-ports, system port start values, kinds) comes out as a reload would.
class SystemCopier {
public:
    Status copyInto(System& to, const System& from)
    {
        copySettings(to, from);
        copySystemParameters(to, from);
        to.layout = from.layout;
        to.preservedXml = from.preservedXml;
        for (const Component* c : from.componentsInOrder()) {
            const Status copied = c->isSystem() ? copySubsystem(to, static_cast<const System&>(*c))
                                                : copyComponent(to, *c);
            if (!copied) return copied;
        }
        for (const Port* p : from.ports())
            if (p->kind() == PortKind::System) to.addSystemPort(p->name());
        to.systemPortExtras = from.systemPortExtras;
        to.preservedObjectsXml = from.preservedObjectsXml;
        to.connectionExtras = from.connectionExtras;

        Status connected;
        forEachConnection(from, [&](const SystemConnection& c) {
            if (!connected) return;
            connected = to.connect(c.startComponent, c.startPort, c.endComponent, c.endPort);
        });
        if (!connected) return {StatusCode::InvalidModel, "copying the model: " + connected.message(), from.modelPath()};
        // Again: start values of C-type subsystem ports exist only after connecting.
        copySystemParameters(to, from);
        to.aliases = from.aliases;
        return Status::ok();
    }

private:
    // A root's, or an external subsystem's as its own file gave them (others keep defaults).
    static void copySettings(System& to, const System& from)
    {
        to.externalPath = from.externalPath;
        to.modelDirectory = from.modelDirectory;
        to.startTime = from.startTime;
        to.stopTime = from.stopTime;
        to.preservedDocumentXml = from.preservedDocumentXml;
        to.setSubTypeName(from.subTypeName());
        to.desiredTimestep = from.desiredTimestep;
        to.inheritTimestep = from.inheritTimestep;
        to.requestedLogSamples = from.requestedLogSamples;
        to.logStartTime = from.logStartTime;
    }

    // As a model file lists them: the system's own parameters, then the start values of
    // its system ports. A value the original refused on load is not in it, so none fails.
    static void copySystemParameters(System& to, const System& from)
    {
        for (const auto& p : from.parameters().all())
            if (!p->isStartValue)
                to.setSystemParameter(p->name, p->value, parameterTypeName(p->type), p->description, p->unit, p->internal);
        if (!from.externalPath.empty()) return;   // an external subsystem's file holds them
        for (const auto& p : from.parameters().all())
            if (p->isStartValue) to.setSystemParameter(p->name, p->value, "double", {}, {}, false);
    }

    Status copySubsystem(System& parent, const System& from)
    {
        auto sub = std::make_unique<System>();
        if (from.isConditional()) sub->makeConditional();
        sub->setNameRaw(from.name());
        sub->setDisabled(from.isDisabled());
        System& to = *sub;
        parent.addComponent(std::move(sub));
        return copyInto(to, from);
    }

    static Status copyComponent(System& parent, const Component& from)
    {
        std::unique_ptr<Component> to = ComponentFactory::instance().create(from.typeName());
        if (!to)
            return {StatusCode::UnknownComponentType,
                    "component type '" + from.typeName() + "' is not in the component factory", from.modelPath()};
        to->setNameRaw(from.name());
        to->setSubTypeName(from.subTypeName());
        to->setDisabled(from.isDisabled());
        to->layout = from.layout;
        to->preservedXml = from.preservedXml;
        Component& added = *to;
        parent.addComponent(std::move(to));
        // The component's own parameters first: they say where an external definition is,
        // which brings the rest.
        for (const auto& p : from.parameters().all())
            if (Parameter* target = added.parameters().find(p->name)) target->value = p->value;
        if (Status loaded = added.loadExternalDefinition(); !loaded)
            return {loaded.code(), "copying the model: " + loaded.message(), from.modelPath()};
        for (const auto& p : from.parameters().all()) {
            Parameter* target = added.parameters().find(p->name);
            if (!target)
                return {StatusCode::InvalidModel, "copying the model: a new " + from.typeName() +
                                                      " has no parameter '" + p->name + "'",
                        from.modelPath() + "." + p->name};
            target->value = p->value;
        }
        for (const Port* p : from.ports()) {
            if (p->signalQuantity.empty()) continue;
            if (Port* q = added.port(p->name())) {
                q->signalQuantity = p->signalQuantity;
                if (q->node()) q->node()->signalQuantity = p->signalQuantity;
            }
        }
        return Status::ok();
    }
};

} // namespace

Result<std::unique_ptr<System>> copySystem(const System& root)
{
    auto copy = std::make_unique<System>();
    copy->setNameRaw(root.name());
    if (Status copied = SystemCopier().copyInto(*copy, root); !copied) return copied;
    return copy;
}

} // namespace tlmhub
