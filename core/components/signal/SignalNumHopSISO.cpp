#include "core/components/signal/SignalNumHopSISO.h"

#include "core/ComponentFactory.h"
#include "core/ParameterEvaluator.h"

#include <muParser.h>

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <vector>

// NumHop -> muParser translation.
//
// The NumHop text is parsed with NumHop's own rules (utilities.md §21: split at
// LF/CR/';'/'#', '#' comments, spaces ignored, four precedence levels tried from
// the loosest, left-to-right accumulators, comparisons binding tighter than
// + - * /, truth = "> 0.5") and re-emitted as a fully parenthesised muParser
// expression, so muParser's own precedence never matters. Every operator that
// differs from muParser's is emitted as a call of a helper function defined
// below; numbers become named constants holding the exact strtod() value.
//
// Supported: assignments, + - | * / & ^ < >, parentheses, numbers (anything
// strtod accepts), `pi`, the NumHop one- and two-argument functions, `in`,
// `out`, script-local variables, and read-only Hopsan names (`self.X`, parent
// system parameters) which are evaluated ONCE at initialisation as constants.
// Not supported / differences:
//  * assigning to a Hopsan parameter name (self.X = ...) is rejected;
//  * a name is a script-local variable if it is assigned anywhere in the
//    script; it starts at 0, so reading it before its first assignment does not
//    fail as it would in NumHop;
//  * function arguments are split at top-level commas only, so nested calls
//    with two arguments (max(a,min(b,c))) are accepted where NumHop fails;
//  * parameter values referenced by name do not follow changes made during
//    the simulation.

namespace tlmhub {

namespace {

double nhOr(double a, double b)
{
    const double ba = a > 0.5 ? 1.0 : 0.0, bb = b > 0.5 ? 1.0 : 0.0;
    return (ba + bb) > 0.5 ? 1.0 : 0.0;
}
double nhAnd(double a, double b) { return (a > 0.5 ? 1.0 : 0.0) * (b > 0.5 ? 1.0 : 0.0); }
double nhLt(double a, double b) { return a < b ? 1.0 : 0.0; }
double nhGt(double a, double b) { return a > b ? 1.0 : 0.0; }
double nhPow(double a, double b) { return std::pow(a, b); }
double nhAbs(double a) { return std::fabs(a); }
double nhAcos(double a) { return std::acos(a); }
double nhAsin(double a) { return std::asin(a); }
double nhAtan(double a) { return std::atan(a); }
double nhCeil(double a) { return std::ceil(a); }
double nhCos(double a) { return std::cos(a); }
double nhCosh(double a) { return std::cosh(a); }
double nhExp(double a) { return std::exp(a); }
double nhFloor(double a) { return std::floor(a); }
double nhLog(double a) { return std::log(a); }
double nhLog10(double a) { return std::log10(a); }
double nhSin(double a) { return std::sin(a); }
double nhSinh(double a) { return std::sinh(a); }
double nhSqrt(double a) { return std::sqrt(a); }
double nhTan(double a) { return std::tan(a); }
double nhTanh(double a) { return std::tanh(a); }
double nhAtan2(double y, double x) { return std::atan2(y, x); }
double nhFmod(double a, double b) { return std::fmod(a, b); }
double nhMin(double a, double b) { return (b < a) ? b : a; }
double nhMax(double a, double b) { return (a < b) ? b : a; }

const std::set<std::string> kFun1 = {"abs", "acos", "asin", "atan", "ceil", "cos", "cosh", "exp", "floor",
                                     "log", "log10", "sin", "sinh", "sqrt", "tan", "tanh"};
const std::set<std::string> kFun2 = {"atan2", "pow", "fmod", "min", "max"};

bool isOperator(char c)
{
    return c == '+' || c == '-' || c == '*' || c == '/' || c == '^' || c == '<' || c == '>' || c == '&' || c == '|'
           || c == '=';
}

// Translates one NumHop expression into muParser text.
class Translator {
public:
    std::map<std::string, std::string> names;  // NumHop name -> muParser identifier
    std::vector<double> constants;             // nhcK values
    std::set<std::string> locals;              // names assigned somewhere in the script
    std::string error;

    bool translate(const std::string& e, std::string& out) { return expr(e, out, true); }

    std::string nameFor(const std::string& n)
    {
        auto it = names.find(n);
        if (it != names.end()) { return it->second; }
        const std::string id = "nhv" + std::to_string(names.size());
        names.emplace(n, id);
        return id;
    }

private:
    bool fail(const std::string& msg)
    {
        if (error.empty()) { error = msg; }
        return false;
    }

    // Index of the ')' matching the '(' at i, or npos.
    static std::size_t matching(const std::string& s, std::size_t i)
    {
        int depth = 0;
        for (std::size_t k = i; k < s.size(); ++k) {
            if (s[k] == '(') { ++depth; }
            else if (s[k] == ')') {
                if (--depth == 0) { return k; }
            }
        }
        return std::string::npos;
    }

    // True if the +/- at i is the exponent sign of a number such as 1e-3.
    static bool isExponentSign(const std::string& s, std::size_t i)
    {
        return i >= 2 && (s[i - 1] == 'e' || s[i - 1] == 'E') && std::isdigit(static_cast<unsigned char>(s[i - 2]));
    }

    bool expr(std::string s, std::string& out, bool topLevel)
    {
        if (s.empty()) { return fail("empty expression"); }
        // Unwrap one enclosing pair of parentheses.
        while (s.front() == '(' && matching(s, 0) == s.size() - 1) {
            s = s.substr(1, s.size() - 2);
            if (s.empty()) { return fail("empty parentheses"); }
        }

        // Depth-0 operator positions.
        std::vector<std::size_t> eqs, addOps, mulOps, powOps;
        int depth = 0;
        for (std::size_t i = 0; i < s.size(); ++i) {
            const char c = s[i];
            if (c == '(') { ++depth; continue; }
            if (c == ')') {
                if (--depth < 0) { return fail("unbalanced parentheses in '" + s + "'"); }
                continue;
            }
            if (depth != 0) { continue; }
            if (c == '=') { eqs.push_back(i); }
            else if ((c == '+' || c == '-') && !isExponentSign(s, i)) { addOps.push_back(i); }
            else if (c == '|') { addOps.push_back(i); }
            else if (c == '*' || c == '/' || c == '&') { mulOps.push_back(i); }
            else if (c == '^' || c == '<' || c == '>') { powOps.push_back(i); }
        }
        if (depth != 0) { return fail("unbalanced parentheses in '" + s + "'"); }

        // Level 1: assignment.
        if (!eqs.empty()) {
            if (eqs.size() != 1 || !topLevel) { return fail("invalid assignment in '" + s + "'"); }
            const std::size_t i = eqs[0];
            if (i == 0 || isOperator(s[i - 1])) { return fail("invalid assignment in '" + s + "'"); }
            if (i + 1 >= s.size() || std::string("=*/^<>&|").find(s[i + 1]) != std::string::npos) {
                return fail("invalid assignment in '" + s + "'");
            }
            const std::string lhs = s.substr(0, i);
            if (lhs == "pi" || lhs.find('.') != std::string::npos || !isName(lhs)) {
                return fail("cannot assign to '" + lhs + "'");
            }
            std::string rhs;
            if (!expr(s.substr(i + 1), rhs, false)) { return false; }
            out = nameFor(lhs) + "=(" + rhs + ")";
            return true;
        }

        // Level 2: + - | accumulated from 0, left to right.
        if (!addOps.empty()) {
            std::string acc;
            char pendingSign = '+';
            bool haveSign = false;
            std::size_t start = 0;
            auto flush = [&](const std::string& term, char op) -> bool {
                std::string t;
                if (!expr(term, t, false)) { return false; }
                if (acc.empty()) {
                    if (op == '+') { acc = "(" + t + ")"; }
                    else if (op == '-') { acc = "(0-(" + t + "))"; }
                    else { acc = "nhOr(0,(" + t + "))"; }
                } else if (op == '|') {
                    acc = "nhOr(" + acc + ",(" + t + "))";
                } else {
                    acc = "(" + acc + std::string(1, op) + "(" + t + "))";
                }
                return true;
            };
            for (std::size_t k = 0; k <= addOps.size(); ++k) {
                const std::size_t end = (k < addOps.size()) ? addOps[k] : s.size();
                const std::string term = s.substr(start, end - start);
                if (term.empty()) {
                    // Only runs of +/- may be adjacent (a leading sign is fine too).
                    if (k < addOps.size()) {
                        const char op = s[addOps[k]];
                        if (op == '|' || (haveSign && pendingSign == '|')) {
                            return fail("operator followed by operator in '" + s + "'");
                        }
                        if (haveSign && op == '-') { pendingSign = (pendingSign == '-') ? '+' : '-'; }
                        else if (!haveSign) { pendingSign = op; }
                        haveSign = true;
                        start = end + 1;
                        continue;
                    }
                    return fail("missing operand in '" + s + "'");
                }
                if (!flush(term, pendingSign)) { return false; }
                if (k < addOps.size()) {
                    pendingSign = s[addOps[k]];
                    haveSign = true;
                    start = end + 1;
                }
            }
            out = acc;
            return true;
        }

        // Level 3: * / & left to right; the first factor starts the accumulator.
        if (!mulOps.empty()) {
            std::string acc;
            std::size_t start = 0;
            char op = 0;
            for (std::size_t k = 0; k <= mulOps.size(); ++k) {
                const std::size_t end = (k < mulOps.size()) ? mulOps[k] : s.size();
                const std::string term = s.substr(start, end - start);
                if (term.empty()) { return fail("missing operand in '" + s + "'"); }
                std::string t;
                if (!expr(term, t, false)) { return false; }
                if (op == 0) { acc = "(" + t + ")"; }
                else if (op == '&') { acc = "nhAnd(" + acc + ",(" + t + "))"; }
                else { acc = "(" + acc + std::string(1, op) + "(" + t + "))"; }
                if (k < mulOps.size()) {
                    op = s[mulOps[k]];
                    start = end + 1;
                }
            }
            out = acc;
            return true;
        }

        // Level 4: a single ^ < or >.
        if (!powOps.empty()) {
            if (powOps.size() != 1) { return fail("chained ^ < > in '" + s + "'"); }
            const std::size_t i = powOps[0];
            std::string l, r;
            if (i == 0 || i + 1 >= s.size()) { return fail("missing operand in '" + s + "'"); }
            if (!expr(s.substr(0, i), l, false) || !expr(s.substr(i + 1), r, false)) { return false; }
            const char* fn = (s[i] == '^') ? "nhPow" : (s[i] == '<') ? "nhLt" : "nhGt";
            out = std::string(fn) + "((" + l + "),(" + r + "))";
            return true;
        }

        return atom(s, out);
    }

    static bool isName(const std::string& s)
    {
        if (s.empty() || std::isdigit(static_cast<unsigned char>(s[0]))) { return false; }
        for (char c : s) {
            if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '.') { return false; }
        }
        return true;
    }

    bool atom(const std::string& s, std::string& out)
    {
        // Function call.
        const std::size_t lp = s.find('(');
        if (lp != std::string::npos && lp > 0 && std::isalpha(static_cast<unsigned char>(s[0]))
            && s.back() == ')' && matching(s, lp) == s.size() - 1) {
            const std::string fname = s.substr(0, lp);
            for (char c : fname) {
                if (!std::isalnum(static_cast<unsigned char>(c))) { return fail("bad function name '" + fname + "'"); }
            }
            const std::string inner = s.substr(lp + 1, s.size() - lp - 2);
            std::vector<std::string> args;
            int depth = 0;
            std::size_t start = 0;
            for (std::size_t k = 0; k < inner.size(); ++k) {
                if (inner[k] == '(') { ++depth; }
                else if (inner[k] == ')') { --depth; }
                else if (inner[k] == ',' && depth == 0) {
                    args.push_back(inner.substr(start, k - start));
                    start = k + 1;
                }
            }
            args.push_back(inner.substr(start));
            const bool one = kFun1.count(fname) != 0, two = kFun2.count(fname) != 0;
            if ((!one && !two) || (one && args.size() != 1) || (two && args.size() != 2)) {
                return fail("unknown function or wrong argument count: '" + s + "'");
            }
            std::string call = "nh" + std::string(1, static_cast<char>(std::toupper(fname[0]))) + fname.substr(1) + "(";
            for (std::size_t k = 0; k < args.size(); ++k) {
                std::string a;
                if (!expr(args[k], a, false)) { return false; }
                call += (k ? ",(" : "(") + a + ")";
            }
            out = call + ")";
            return true;
        }
        // Number: anything strtod consumes completely.
        {
            char* end = nullptr;
            errno = 0;
            const double v = std::strtod(s.c_str(), &end);
            if (end == s.c_str() + s.size()) {
                out = "nhc" + std::to_string(constants.size());
                constants.push_back(v);
                return true;
            }
        }
        if (!isName(s)) { return fail("syntax error at '" + s + "'"); }
        if (s == "pi") {
            out = "nhc" + std::to_string(constants.size());
            constants.push_back(3.14159265358979323846);
            return true;
        }
        out = nameFor(s);
        return true;
    }
};

// Split a script into NumHop expressions (LF, CR, ';', '#' comments), spaces removed.
std::vector<std::string> splitScript(const std::string& script)
{
    std::vector<std::string> parts;
    std::string cur;
    bool comment = false;
    auto push = [&]() {
        std::string e;
        for (char c : cur) {
            if (c != ' ' && c != '\t') { e += c; }
        }
        if (!e.empty()) { parts.push_back(e); }
        cur.clear();
    };
    for (char c : script) {
        if (c == '\n' || c == '\r') {
            comment = false;
            push();
        } else if (comment) {
            continue;
        } else if (c == '#') {
            comment = true;
            push();
        } else if (c == ';') {
            push();
        } else {
            cur += c;
        }
    }
    push();
    return parts;
}

} // namespace

SignalNumHopSISO::SignalNumHopSISO() = default;
SignalNumHopSISO::~SignalNumHopSISO() = default;

void SignalNumHopSISO::configure()
{
    addInputVariable("in", "Input", "", 0.0, &mpIn);
    addOutputVariable("out", "Output", "", &mpOut);
    addConstant("scriptfile", "Script file", std::string(), mScriptFile, ParameterType::String);
}

bool SignalNumHopSISO::evaluateScript()
{
    mIn = *mpIn;
    try {
        mpParser->Eval();
    } catch (const mu::Parser::exception_type& e) {
        stopSimulation("SignalNumHopSISO: script evaluation failed: " + e.GetMsg());
        return false;
    }
    *mpOut = mOut;
    return true;
}

void SignalNumHopSISO::initialize()
{
    const std::string path = findFilePath(mScriptFile);
    std::ifstream file(path);
    if (!file) {
        stopSimulation("SignalNumHopSISO: cannot open script file '" + path + "'");
        return;
    }
    std::stringstream buffer;
    buffer << file.rdbuf();
    const std::vector<std::string> exprs = splitScript(buffer.str());
    if (exprs.empty()) {
        stopSimulation("SignalNumHopSISO: the script '" + path + "' is empty");
        return;
    }

    Translator tr;
    tr.nameFor("in");
    tr.nameFor("out");
    // Names assigned anywhere become script-local variables.
    for (const std::string& e : exprs) {
        const std::size_t eq = e.find('=');
        if (eq != std::string::npos && eq > 0) { tr.locals.insert(e.substr(0, eq)); }
    }
    std::string muExpr;
    for (const std::string& e : exprs) {
        std::string t;
        if (!tr.translate(e, t)) {
            stopSimulation("SignalNumHopSISO: cannot interpret '" + e + "': " + tr.error);
            return;
        }
        muExpr += (muExpr.empty() ? "" : ",") + t;
    }

    mStorage.clear();
    mIn = *mpIn;
    mOut = *mpOut;
    try {
        mpParser = std::make_unique<mu::Parser>();
        mu::Parser& p = *mpParser;
        p.DefineFun("nhOr", nhOr);
        p.DefineFun("nhAnd", nhAnd);
        p.DefineFun("nhLt", nhLt);
        p.DefineFun("nhGt", nhGt);
        p.DefineFun("nhPow", nhPow);
        p.DefineFun("nhAbs", nhAbs);
        p.DefineFun("nhAcos", nhAcos);
        p.DefineFun("nhAsin", nhAsin);
        p.DefineFun("nhAtan", nhAtan);
        p.DefineFun("nhCeil", nhCeil);
        p.DefineFun("nhCos", nhCos);
        p.DefineFun("nhCosh", nhCosh);
        p.DefineFun("nhExp", nhExp);
        p.DefineFun("nhFloor", nhFloor);
        p.DefineFun("nhLog", nhLog);
        p.DefineFun("nhLog10", nhLog10);
        p.DefineFun("nhSin", nhSin);
        p.DefineFun("nhSinh", nhSinh);
        p.DefineFun("nhSqrt", nhSqrt);
        p.DefineFun("nhTan", nhTan);
        p.DefineFun("nhTanh", nhTanh);
        p.DefineFun("nhAtan2", nhAtan2);
        p.DefineFun("nhFmod", nhFmod);
        p.DefineFun("nhMin", nhMin);
        p.DefineFun("nhMax", nhMax);
        for (std::size_t k = 0; k < tr.constants.size(); ++k) {
            p.DefineConst("nhc" + std::to_string(k), tr.constants[k]);
        }
        for (const auto& [name, id] : tr.names) {
            if (name == "in") { p.DefineVar(id, &mIn); continue; }
            if (name == "out") { p.DefineVar(id, &mOut); continue; }
            mStorage.push_back(0.0);
            double* slot = &mStorage.back();
            if (tr.locals.count(name) == 0) {
                // A Hopsan name (self.X or a system parameter): read once, here.
                const Result<double> value = ParameterEvaluator::evaluateExpression(*this, name);
                if (!value) {
                    stopSimulation("SignalNumHopSISO: unknown name '" + name + "' in script: " +
                                   value.status().message());
                    return;
                }
                *slot = *value;
            }
            p.DefineVar(id, slot);
        }
        p.SetExpr(muExpr);
    } catch (const mu::Parser::exception_type& e) {
        stopSimulation("SignalNumHopSISO: cannot interpret the script: " + e.GetMsg());
        return;
    }
    // Interpreted once; one evaluation is part of initialisation.
    evaluateScript();
}

void SignalNumHopSISO::simulateOneTimestep()
{
    evaluateScript();
}

TLMHUB_REGISTER_COMPONENT(SignalNumHopSISO, "Signal")

} // namespace tlmhub
