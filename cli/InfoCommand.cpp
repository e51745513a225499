#include "cli/Commands.h"

#include "core/hmf/HmfLoader.h"

#include <cstdio>
#include <iostream>

namespace tlmhub::cli {

namespace {

void describe(const System& sys, const std::string& indent)
{
    std::printf("%ssystem %s: Ts=%g%s, %zu components\n", indent.c_str(), sys.name().c_str(),
                sys.desiredTimestep, sys.inheritTimestep ? " (inherited)" : "",
                sys.componentsInOrder().size());
    for (const auto& p : sys.parameters().all())
        std::printf("%s  system parameter %s = %s\n", indent.c_str(), p->name.c_str(), p->value.c_str());
    for (Component* c : sys.componentsByName()) {
        std::printf("%s  %s : %s [%s]%s\n", indent.c_str(), c->name().c_str(), c->typeName().c_str(),
                    cqsKindName(c->kind()), c->isDisabled() ? " disabled" : "");
        for (const auto& p : c->parameters().all())
            if (p->value != p->defaultValue)
                std::printf("%s      %s = %s\n", indent.c_str(), p->name.c_str(), p->value.c_str());
        for (const auto& [name, port] : c->portsByName()) {
            const std::string& pname = name;   // clang 14 cannot capture a structured binding
            auto printConn = [&](const Port* from) {
                for (const Port* q : from->connectedPorts) {
                    const std::string other = q->component() == &sys ? q->name() : q->component()->name();
                    std::printf("%s      %s.%s -- %s.%s\n", indent.c_str(), c->name().c_str(),
                                pname.c_str(), other.c_str(), q->name().c_str());
                }
            };
            if (port->isMultiport())
                for (const auto& sub : port->subPorts) printConn(sub.get());
            else
                printConn(port);
        }
        if (c->isSystem()) describe(*static_cast<const System*>(c), indent + "    ");
    }
}

} // namespace

int infoCommand(const std::vector<std::string>& args)
{
    if (args.size() != 1) {
        std::cerr << "tlmhub-cli info: expected one model file\n";
        return 2;
    }
    LoadedModel model = loadHmfFile(args[0]);
    for (const auto& m : model.messages)
        if (m.type == MessageType::Warning) std::cerr << "warning: " << m.text << "\n";
    if (model.hasErrors()) {
        std::cerr << "error: " << model.firstError() << "\n";
        return 1;
    }
    const System& root = *model.root;
    std::printf("model %s: start %g, stop %g, log samples %zu\n", args[0].c_str(), root.startTime,
                root.stopTime, root.requestedLogSamples);
    describe(root, "");
    return 0;
}

} // namespace tlmhub::cli
