// --resultsFullCSV and --resultsFinalCSV: the logged variables in core.md §4.5's names and
// order (core's listLoggedVariables), one line each, with a "<path>Time" line after each
// system's content; "cols" writes the transpose.
#include "cli/hopsancli/HopsanCli.h"

#include "core/Node.h"
#include "core/Port.h"
#include "core/Results.h"
#include "core/System.h"

#include <algorithm>
#include <cstdio>

namespace tlmhub::hopsancli {

namespace {

using Line = std::vector<std::string>;

std::string number(double value)
{
    char text[64];
    std::snprintf(text, sizeof text, "%e", value);
    return text;
}

// "Sub1$Sub2$" for a subsystem, "" for the root.
std::string systemPrefix(const System& system)
{
    return system.isRoot() ? std::string() : systemPrefix(*system.parentSystem()) + system.name() + "$";
}

// The alias a system gives "Comp#Port#Var", if any.
std::string aliasOf(const System& system, const std::string& localName)
{
    for (const auto& [alias, target] : system.aliases)
        if (target == localName) return alias;
    return {};
}

bool selected(const LoggedVariable& v, const std::vector<std::string>& only)
{
    if (only.empty()) return true;
    const std::string portName = v.fullName.substr(0, v.fullName.rfind('#'));
    return std::find(only.begin(), only.end(), portName) != only.end() ||
           std::find(only.begin(), only.end(), v.fullName) != only.end();
}

Line timeLine(const System& system, ResultAmount amount)
{
    Line line{systemPrefix(system) + "Time", "", "s"};
    if (amount == ResultAmount::Final) {
        line.push_back(number(system.time()));
    } else {
        const std::vector<double>& time = system.logTime();
        const std::size_t n = std::min(system.numLoggedSamples(), time.size());
        for (std::size_t i = 0; i < n; ++i) line.push_back(number(time[i]));
    }
    return line;
}

Line variableLine(const LoggedVariable& v, ResultAmount amount)
{
    const std::string local = v.fullName.substr(v.fullName.rfind('$') + 1);
    Line line{v.fullName, aliasOf(*v.owner, local), v.unit};
    if (amount == ResultAmount::Final) {
        line.push_back(number(v.port->node()->value(v.slot)));
    } else {
        for (double x : loggedData(*v.port, v.slot, v.owner->numLoggedSamples())) line.push_back(number(x));
    }
    return line;
}

// The systems from the root down to `system`.
std::vector<const System*> chainTo(const System* system)
{
    std::vector<const System*> chain;
    for (; system; system = system->parentSystem()) chain.insert(chain.begin(), system);
    return chain;
}

std::vector<Line> resultLines(const System& root, ResultAmount amount, const std::vector<std::string>& only)
{
    // The systems whose content is being written, outermost first, each with whether one of
    // its own components gave a line: a system's Time line follows its content only then.
    struct Open {
        const System* system;
        bool hasLines;
    };
    std::vector<Open> open;
    std::vector<Line> lines;
    auto closeTo = [&](std::size_t depth) {
        while (open.size() > depth) {
            if (open.back().hasLines) lines.push_back(timeLine(*open.back().system, amount));
            open.pop_back();
        }
    };
    for (const LoggedVariable& v : listLoggedVariables(root)) {
        if (!selected(v, only)) continue;
        const std::vector<const System*> chain = chainTo(v.owner);
        std::size_t common = 0;
        while (common < open.size() && common < chain.size() && open[common].system == chain[common]) ++common;
        closeTo(common);
        for (std::size_t i = common; i < chain.size(); ++i) open.push_back({chain[i], false});
        open.back().hasLines = true;
        lines.push_back(variableLine(v, amount));
    }
    closeTo(0);
    return lines;
}

} // namespace

bool writeResultsCsv(const System& root, const std::string& path, ResultAmount amount,
                     const std::vector<std::string>& only, bool columns, std::string& error)
{
    const std::vector<Line> lines = resultLines(root, amount, only);
    std::FILE* f = std::fopen(path.c_str(), "w");
    if (!f) {
        error = "Could not open: " + path + " for writing!";
        return false;
    }
    std::string text;
    auto put = [&](const std::string& piece) {
        text += piece;
        if (text.size() > (1u << 16)) {
            std::fwrite(text.data(), 1, text.size(), f);
            text.clear();
        }
    };
    if (!columns) {
        for (const Line& line : lines) {
            for (std::size_t i = 0; i < line.size(); ++i) put(i ? "," + line[i] : line[i]);
            put("\n");
        }
    } else {
        // Column c of every line makes line c; a line shorter than the longest (a subsystem
        // that logged fewer samples) leaves its cell empty.
        std::size_t width = 0;
        for (const Line& line : lines) width = std::max(width, line.size());
        for (std::size_t c = 0; c < width; ++c) {
            for (std::size_t r = 0; r < lines.size(); ++r) {
                if (r) put(",");
                if (c < lines[r].size()) put(lines[r][c]);
            }
            put("\n");
        }
    }
    std::fwrite(text.data(), 1, text.size(), f);
    const bool ok = !std::ferror(f);
    if (std::fclose(f) != 0 || !ok) {
        error = "Could not write: " + path;
        return false;
    }
    return true;
}

} // namespace tlmhub::hopsancli
