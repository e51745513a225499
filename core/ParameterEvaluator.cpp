#include "core/ParameterEvaluator.h"

#include "core/Component.h"
#include "core/Parameter.h"
#include "core/System.h"

#include <muParser.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <deque>
#include <vector>

namespace tlmhub::ParameterEvaluator {

namespace {

constexpr int kMaxDepth = 250;
std::atomic<std::size_t> gDefaultBudget{kDefaultBudget};

bool parseWholeDouble(const std::string& s, double& out)
{
    if (s.empty() || std::isspace(static_cast<unsigned char>(s.front()))) return false;
    char* end = nullptr;
    errno = 0;
    double v = std::strtod(s.c_str(), &end);
    if (end != s.c_str() + s.size()) return false;
    out = v;
    return true;
}

bool parseWholeInt(const std::string& s, int& out)
{
    if (s.empty()) return false;
    char* end = nullptr;
    long v = std::strtol(s.c_str(), &end, 10);
    if (end != s.c_str() + s.size()) return false;
    out = static_cast<int>(v);
    return true;
}

bool evaluateDepth(Component& owner, Parameter& param, std::string& error, int depth, Pass& pass);

// A named parameter visible from `owner`: "self.X" / "self.P.V" on the owner itself,
// otherwise a system parameter from the owner's system (systems: themselves first) upwards.
Parameter* lookupName(Component& owner, const std::string& name, Component*& where,
                      const Parameter* exclude)
{
    if (name.rfind("self.", 0) == 0) {
        std::string rest = name.substr(5);
        for (char& c : rest)
            if (c == '.') c = '#';
        Parameter* p = owner.parameters().find(rest);
        if (!p) p = owner.parameters().find(rest + "#Value");
        where = &owner;
        return p;
    }
    System* s = owner.isSystem() ? static_cast<System*>(&owner) : owner.parentSystem();
    for (; s; s = s->parentSystem()) {
        Parameter* p = s->parameters().find(name);
        if (p && p != exclude && !p->isStartValue) {
            where = s;
            return p;
        }
    }
    return nullptr;
}

double mathLog(double x) { return std::log(x); }
double mathCeil(double x) { return std::ceil(x); }
double mathFloor(double x) { return std::floor(x); }
double mathAtan2(double y, double x) { return std::atan2(y, x); }
double mathPow(double x, double y) { return std::pow(x, y); }
double mathFmod(double x, double y) { return std::fmod(x, y); }
double mathMin(double x, double y) { return std::fmin(x, y); }
double mathMax(double x, double y) { return std::fmax(x, y); }
double logicAnd(double a, double b) { return (a > 0.5 && b > 0.5) ? 1.0 : 0.0; }
double logicOr(double a, double b) { return (a > 0.5 || b > 0.5) ? 1.0 : 0.0; }

double* variableFactory(const mu::char_type*, void* user)
{
    auto* pool = static_cast<std::deque<double>*>(user);
    pool->push_back(0.0);
    return &pool->back();
}

// `chain`: the parameters whose values are being evaluated, outermost first. A reference to
// one of them is a loop and fails at once; only the depth limit stopped loops before, after
// 250 levels per branch (a self.k in k's own expression cost seconds).
bool evaluateExpressionDepth(Component& owner, const std::string& expression, double& result,
                             std::string& error, const Parameter* self, int depth,
                             std::vector<const Parameter*>& chain, Pass& pass)
{
    if (depth > kMaxDepth) {
        error = "parameter references nest too deeply (a reference loop?)";
        return false;
    }
    if (pass.evaluations >= pass.budget) {
        error = "more than " + std::to_string(pass.budget) +
                " parameter expressions to evaluate (the evaluation limit), at '" + expression + "'";
        return false;
    }
    ++pass.evaluations;
    std::deque<double> pool;
    try {
        mu::Parser parser;
        parser.DefineNameChars("0123456789_abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ.#");
        parser.DefineConst("pi", 3.14159265358979323846);
        parser.DefineFun("log", mathLog);
        parser.DefineFun("ceil", mathCeil);
        parser.DefineFun("floor", mathFloor);
        parser.DefineFun("atan2", mathAtan2);
        parser.DefineFun("pow", mathPow);
        parser.DefineFun("fmod", mathFmod);
        parser.DefineFun("min", mathMin);
        parser.DefineFun("max", mathMax);
        parser.DefineOprt("&", logicAnd, mu::prLOGIC);
        parser.DefineOprt("|", logicOr, mu::prLOGIC);
        parser.SetVarFactory(variableFactory, &pool);
        parser.SetExpr(expression);
        const mu::varmap_type used = parser.GetUsedVar();
        for (const auto& [name, ptr] : used) {
            Component* where = nullptr;
            Parameter* ref = lookupName(owner, name, where, self);
            if (!ref) {
                error = "unknown name '" + name + "' in expression '" + expression + "'";
                return false;
            }
            double v = 0.0;
            if (ref->type == ParameterType::Double) {
                if (parseWholeDouble(ref->value, v)) {
                } else if (const auto known = pass.values.find(ref); known != pass.values.end()) {
                    v = known->second;
                } else {
                    if (std::find(chain.begin(), chain.end(), ref) != chain.end()) {
                        error = "'" + name + "' refers to itself (a reference loop)";
                        return false;
                    }
                    chain.push_back(ref);
                    const bool ok = evaluateExpressionDepth(*where, ref->value, v, error, ref, depth + 1, chain, pass);
                    chain.pop_back();
                    if (!ok) return false;
                    pass.values.emplace(ref, v);
                }
            } else if (ref->type == ParameterType::Integer || ref->type == ParameterType::Conditional) {
                int iv = 0;
                if (!parseWholeInt(ref->value, iv)) {
                    error = "'" + name + "' is not a number";
                    return false;
                }
                v = iv;
            } else if (ref->type == ParameterType::Bool) {
                v = (ref->value == "true" || ref->value == "1") ? 1.0 : 0.0;
            } else {
                error = "'" + name + "' is not numeric";
                return false;
            }
            *ptr = v;
        }
        result = parser.Eval();
    } catch (const mu::Parser::exception_type& e) {
        error = "cannot evaluate '" + expression + "': " + e.GetMsg();
        return false;
    }
    return true;
}

// Integer / bool / string parameters: a literal, or a name of a parameter of the same type.
Parameter* lookupSameType(Component& owner, const std::string& name, ParameterType type,
                          Component*& where, const Parameter* self)
{
    Parameter* p = lookupName(owner, name, where, self);
    if (!p) return nullptr;
    const bool intLike = [](ParameterType t) {
        return t == ParameterType::Integer || t == ParameterType::Conditional;
    }(type);
    if (intLike && (p->type == ParameterType::Integer || p->type == ParameterType::Conditional)) return p;
    return p->type == type ? p : nullptr;
}

bool evaluateDepth(Component& owner, Parameter& param, std::string& error, int depth, Pass& pass)
{
    if (depth > kMaxDepth) {
        error = "parameter references nest too deeply (a reference loop?)";
        return false;
    }
    const std::string& v = param.value;
    switch (param.type) {
    case ParameterType::Double: {
        double d = 0.0;
        if (!parseWholeDouble(v, d)) {
            if (const auto known = pass.values.find(&param); known != pass.values.end()) {
                d = known->second;
            } else {
                std::vector<const Parameter*> chain{&param};
                if (!evaluateExpressionDepth(owner, v, d, error, &param, depth + 1, chain, pass)) return false;
                pass.values.emplace(&param, d);
            }
            // Hopsan formats the result with 17 significant digits and parses it back.
            char buf[64];
            std::snprintf(buf, sizeof buf, "%.17g", d);
            d = std::strtod(buf, nullptr);
        }
        if (param.doubleTarget) *param.doubleTarget = d;
        return true;
    }
    case ParameterType::Integer:
    case ParameterType::Conditional: {
        int i = 0;
        if (!parseWholeInt(v, i)) {
            std::size_t pos = 0;
            bool negative = false;
            while (pos < v.size() && (v[pos] == '+' || v[pos] == '-')) {
                if (v[pos] == '-') negative = !negative;
                ++pos;
            }
            Component* where = nullptr;
            Parameter* ref = lookupSameType(owner, v.substr(pos), param.type, where, &param);
            if (!ref) {
                error = "'" + v + "' is not an integer or the name of an integer parameter";
                return false;
            }
            Parameter copy = *ref;
            int inner = 0;
            copy.intTarget = &inner;
            if (!evaluateDepth(*where, copy, error, depth + 1, pass)) return false;
            i = negative ? -inner : inner;
        }
        if (param.type == ParameterType::Conditional && !param.conditions.empty() &&
            (i < 0 || i >= static_cast<int>(param.conditions.size()))) {
            error = "choice " + std::to_string(i) + " out of range 0.." +
                    std::to_string(param.conditions.size() - 1);
            return false;
        }
        if (param.intTarget) *param.intTarget = i;
        return true;
    }
    case ParameterType::Bool: {
        bool b = false;
        if (v == "true" || v == "1") b = true;
        else if (v == "false" || v == "0") b = false;
        else {
            Component* where = nullptr;
            Parameter* ref = lookupSameType(owner, v, ParameterType::Bool, where, &param);
            if (!ref) {
                error = "'" + v + "' is not true/false or the name of a bool parameter";
                return false;
            }
            Parameter copy = *ref;
            bool inner = false;
            copy.boolTarget = &inner;
            if (!evaluateDepth(*where, copy, error, depth + 1, pass)) return false;
            b = inner;
        }
        if (param.boolTarget) *param.boolTarget = b;
        return true;
    }
    default: {
        std::string s = v;
        Component* where = nullptr;
        if (!v.empty()) {
            if (Parameter* ref = lookupSameType(owner, v, param.type, where, &param)) s = ref->value;
        }
        if (param.stringTarget) *param.stringTarget = s;
        return true;
    }
    }
}

} // namespace

void setDefaultBudget(std::size_t evaluations)
{
    gDefaultBudget = evaluations;
}

std::size_t defaultBudget()
{
    return gDefaultBudget;
}

Status evaluate(Component& owner, Parameter& param, Pass& pass)
{
    std::string error;
    if (evaluateDepth(owner, param, error, 0, pass)) return Status::ok();
    const std::string owned = owner.modelPath();
    return {StatusCode::InvalidParameter, error, owned.empty() ? param.name : owned + "." + param.name};
}

Status evaluate(Component& owner, Parameter& param)
{
    Pass pass;
    return evaluate(owner, param, pass);
}

Result<double> evaluateExpression(Component& owner, const std::string& expression)
{
    double result = 0.0;
    if (parseWholeDouble(expression, result)) return result;
    std::vector<const Parameter*> chain;
    std::string error;
    Pass pass;
    if (evaluateExpressionDepth(owner, expression, result, error, nullptr, 0, chain, pass)) return result;
    return Status{StatusCode::InvalidParameter, error, owner.modelPath()};
}

} // namespace tlmhub::ParameterEvaluator
