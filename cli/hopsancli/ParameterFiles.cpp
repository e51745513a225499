// --parameterExport and --parameterImport: "Name,value" lines, named as HopsanCLI names
// parameters ("self#P", "Comp#P", "Comp#Port#Var", "Sub$Comp#P", "Sub$#P").
#include "cli/hopsancli/HopsanCli.h"

#include "core/ParameterPath.h"
#include "core/System.h"

#include <fstream>

namespace tlmhub::hopsancli {

namespace {

void exportSystem(const System& system, const std::string& prefix, std::ofstream& out)
{
    const std::string self = prefix.empty() ? "self" : prefix;
    for (const auto& p : system.parameters().all())
        if (!p->isStartValue) out << self << "#" << p->name << "," << p->value << "\n";
    for (const Component* c : system.componentsByName()) {
        if (c->isSystem()) {
            exportSystem(*static_cast<const System*>(c), prefix + c->name() + "$", out);
            continue;
        }
        for (const auto& p : c->parameters().all()) out << prefix << c->name() << "#" << p->name << "," << p->value << "\n";
    }
}

} // namespace

Component* componentWithFullName(System& root, const std::string& fullName, const Printer& print)
{
    const std::vector<std::string> parts = splitFields(fullName, '$');
    if (parts.empty()) {
        print.error("No component: " + fullName + " in system: " + root.name());
        return nullptr;
    }
    System* system = &root;
    for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
        System* sub = system->subsystem(parts[i]);
        if (!sub) {
            print.error("Subsystem: " + parts[i] + " could not be found in parent system: " + system->name());
            return nullptr;
        }
        system = sub;
    }
    Component* c = system->component(parts.back());
    if (!c) print.error("No component: " + parts.back() + " in system: " + system->name());
    return c;
}

bool exportParameters(const System& root, const std::string& path, const std::string& prefix, std::string& error)
{
    std::ofstream out(path);
    if (!out) {
        error = "Could not open: " + path + " for writing!";
        return false;
    }
    exportSystem(root, prefix, out);
    out.close();
    if (!out) {
        error = "Could not write: " + path;
        return false;
    }
    return true;
}

void importParameters(System& root, const std::string& path, const Printer& print)
{
    std::ifstream in(path);
    if (!in) {
        print.error("Could not open file: " + path);
        return;
    }
    std::string line;
    while (std::getline(in, line)) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.empty() || line[0] == '#') continue;
        const std::vector<std::string> fields = splitFields(line, ',');
        if (fields.size() != 2) {
            print.warning("Wrong line format: " + line);
            continue;
        }
        const std::vector<std::string> nameParts = splitFields(fields[0], '#');
        if (nameParts.size() != 2 && nameParts.size() != 3) {
            print.error(fields[0] + " should be FullComponentName#ParameterName on line: " + line);
            continue;
        }
        const std::string& componentName = nameParts[0];
        const std::string parameterName = nameParts.size() == 2 ? nameParts[1] : nameParts[1] + "#" + nameParts[2];
        Component* owner = componentName == "self" ? &root : componentWithFullName(root, componentName, print);
        if (!owner) continue;
        Parameter* parameter = owner->parameters().find(parameterName);
        // A system's start values are not its parameters in HopsanCLI's sense.
        if (parameter && owner->isSystem() && parameter->isStartValue) parameter = nullptr;
        if (!parameter || !assignParameter(*owner, *parameter, fields[1]))
            print.error("Setting parameter: " + parameterName + " in component: " + componentName);
    }
}

} // namespace tlmhub::hopsancli
