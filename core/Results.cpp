#include "core/Results.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace tlmhub {

namespace {

void splitOn(const std::string& s, char sep, std::vector<std::string>& out)
{
    out.clear();
    std::string cur;
    for (char c : s) {
        if (c == sep) {
            out.push_back(cur);
            cur.clear();
        } else {
            cur += c;
        }
    }
    out.push_back(cur);
}

void collect(const System& sys, const std::string& prefix, std::vector<LoggedVariable>& out)
{
    const std::size_t count = sys.numLoggedSamples();
    for (Component* c : sys.componentsByName()) {
        for (const auto& [pname, p] : c->portsByName()) {
            if (!p->wantsLogging || p->isMultiport()) continue;
            const Node* n = p->node();
            if (!n || n->logData.empty()) continue;
            const auto& vars = nodeTypeInfo(n->type()).variables;
            for (std::size_t i = 0; i < vars.size(); ++i) {
                LoggedVariable v;
                v.fullName = prefix + c->name() + "#" + pname + "#" + std::string(vars[i].name);
                v.unit = n->type() == NodeType::Signal ? n->signalUnit : std::string(vars[i].unit);
                v.port = p;
                v.slot = static_cast<int>(i);
                v.count = count;
                v.owner = &sys;
                out.push_back(std::move(v));
            }
        }
        if (c->isSystem()) {
            const auto* sub = static_cast<const System*>(c);
            collect(*sub, prefix + sub->name() + "$", out);
        }
    }
}

} // namespace

std::vector<LoggedVariable> listLoggedVariables(const System& root)
{
    std::vector<LoggedVariable> out;
    collect(root, "", out);
    return out;
}

const std::vector<double>* loggedTime(const Port& port)
{
    const Node* n = port.node();
    if (!n || !n->logOwner) return nullptr;
    return &n->logOwner->logTime();
}

std::vector<double> loggedData(const Port& port, int slot, std::size_t count)
{
    std::vector<double> out;
    const Node* n = port.node();
    if (!n || n->logData.empty()) return out;
    count = std::min(count, n->logData.samples());
    out.resize(count);
    for (std::size_t i = 0; i < count; ++i) out[i] = n->logData.value(i, slot);
    return out;
}

void appendLoggedData(const Port& port, int slot, std::size_t from, std::size_t to,
                      std::vector<double>& out)
{
    const Node* n = port.node();
    if (!n || n->logData.empty()) return;
    to = std::min(to, n->logData.samples());
    if (from >= to) return;
    out.reserve(out.size() + (to - from));
    for (std::size_t i = from; i < to; ++i) out.push_back(n->logData.value(i, slot));
}

bool findNonFinite(const System& root, std::string& where)
{
    for (const LoggedVariable& v : listLoggedVariables(root)) {
        const std::vector<double> data = loggedData(*v.port, v.slot, v.count);
        const std::vector<double>* time = loggedTime(*v.port);
        for (std::size_t i = 0; i < data.size(); ++i) {
            if (!std::isfinite(data[i])) {
                std::ostringstream os;
                os << v.fullName << " = " << data[i];
                if (time && i < time->size()) os << " at t=" << (*time)[i];
                where = os.str();
                return true;
            }
        }
    }
    // Models without logging: the final node values.
    struct Walker {
        static bool walk(const System& s, const std::string& prefix, std::string& where)
        {
            for (Component* c : s.componentsByName()) {
                for (const auto& [pname, p] : c->portsByName()) {
                    if (p->isMultiport() || !p->node()) continue;
                    const Node* n = p->node();
                    for (std::size_t i = 0; i < n->size(); ++i) {
                        if (!std::isfinite(n->value(static_cast<int>(i)))) {
                            where = prefix + c->name() + "#" + pname + "#" +
                                    std::string(nodeTypeInfo(n->type()).variables[i].name) +
                                    " (final value)";
                            return true;
                        }
                    }
                }
                if (c->isSystem() && walk(*static_cast<const System*>(c), prefix + c->name() + "$", where))
                    return true;
            }
            return false;
        }
    };
    return Walker::walk(root, "", where);
}

Result<VariableRef> resolveVariable(System& root, const std::string& fullName)
{
    std::vector<std::string> fields;
    splitOn(fullName, '$', fields);
    const std::size_t m = fields.size() - 1;
    std::vector<std::string> parts;
    splitOn(fields[m], '#', parts);
    if (parts.size() != 3)
        return Status{StatusCode::NotFound, "variable name '" + fullName + "' is not Component#Port#Variable"};
    System* sys = &root;
    for (std::size_t s = 0; s < m; ++s) {
        if (System* sub = sys->subsystem(fields[s])) {
            sys = sub;
        } else if (s == 0 && m == 1) {
            // "Root$Comp#Port#Var": the first field names the root itself.
        } else if (s == 0 && m >= 2) {
            System* alt = root.subsystem(fields[1]);
            if (!alt)
                return Status{StatusCode::NotFound, "no subsystem '" + fields[1] + "' in '" + root.name() + "'"};
            sys = alt;
        } else {
            return Status{StatusCode::NotFound, "no subsystem '" + fields[s] + "' in '" + sys->name() + "'"};
        }
    }
    Component* c = sys->component(parts[0]);
    if (!c)
        return Status{StatusCode::NotFound, "no component '" + parts[0] + "' in system '" + sys->name() + "'"};
    Port* port = c->port(parts[1]);
    if (!port)
        return Status{StatusCode::NotFound, "component '" + parts[0] + "' has no port '" + parts[1] + "'"};
    const int slot = nodeVariableIndex(port->nodeType(), parts[2]);
    if (slot < 0)
        return Status{StatusCode::NotFound, "port '" + parts[0] + "#" + parts[1] + "' has no variable '" + parts[2] + "'"};
    return VariableRef{port, slot};
}

} // namespace tlmhub
