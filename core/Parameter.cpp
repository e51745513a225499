#include "core/Parameter.h"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <cstdlib>

namespace tlmhub {

const char* parameterTypeName(ParameterType type)
{
    switch (type) {
    case ParameterType::Double: return "double";
    case ParameterType::Integer: return "integer";
    case ParameterType::Bool: return "bool";
    case ParameterType::String: return "string";
    case ParameterType::TextBlock: return "textblock";
    case ParameterType::FilePath: return "filepath";
    case ParameterType::Conditional: return "conditional";
    }
    return "double";
}

bool parameterTypeFromName(const std::string& name, ParameterType& out)
{
    static const std::pair<const char*, ParameterType> names[] = {
        {"double", ParameterType::Double},   {"integer", ParameterType::Integer},
        {"int", ParameterType::Integer},     {"bool", ParameterType::Bool},
        {"string", ParameterType::String},   {"textblock", ParameterType::TextBlock},
        {"filepath", ParameterType::FilePath}, {"conditional", ParameterType::Conditional},
    };
    for (const auto& [n, t] : names) {
        if (name == n) {
            out = t;
            return true;
        }
    }
    return false;
}

void Parameter::bindOwnStorage()
{
    doubleTarget = nullptr;
    intTarget = nullptr;
    boolTarget = nullptr;
    stringTarget = nullptr;
    switch (type) {
    case ParameterType::Double: doubleTarget = &ownDouble; break;
    case ParameterType::Integer:
    case ParameterType::Conditional: intTarget = &ownInt; break;
    case ParameterType::Bool: boolTarget = &ownBool; break;
    default: stringTarget = &ownString; break;
    }
}

Parameter* ParameterSet::find(const std::string& name)
{
    for (auto& p : mParameters)
        if (p->name == name) return p.get();
    return nullptr;
}

const Parameter* ParameterSet::find(const std::string& name) const
{
    for (const auto& p : mParameters)
        if (p->name == name) return p.get();
    return nullptr;
}

Parameter& ParameterSet::add(Parameter p)
{
    if (Parameter* existing = find(p.name)) {
        *existing = std::move(p);
        return *existing;
    }
    mParameters.push_back(std::make_unique<Parameter>(std::move(p)));
    return *mParameters.back();
}

bool ParameterSet::remove(const std::string& name)
{
    auto it = std::find_if(mParameters.begin(), mParameters.end(),
                           [&](const auto& p) { return p->name == name; });
    if (it == mParameters.end()) return false;
    mParameters.erase(it);
    return true;
}

bool ParameterSet::rename(const std::string& oldName, const std::string& newName)
{
    Parameter* p = find(oldName);
    if (!p || find(newName)) return false;
    p->name = newName;
    return true;
}

std::string formatNumber(double value)
{
    // Shortest text that reads back as the same double.
    char buf[64];
    const auto result = std::to_chars(buf, buf + sizeof buf, value);
    return std::string(buf, result.ptr);
}

} // namespace tlmhub
