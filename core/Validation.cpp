#include "core/Validation.h"

#include "core/Results.h"
#include "core/Simulation.h"
#include "core/hmf/HmfLoader.h"

#include <pugixml.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <numeric>
#include <optional>
#include <sstream>

namespace tlmhub {

namespace fs = std::filesystem;

std::size_t ValidationReport::passed() const
{
    return std::count_if(variables.begin(), variables.end(), [](const auto& v) { return v.passed; });
}

std::size_t ValidationReport::failed() const { return variables.size() - passed(); }

bool sampleFails(double sim, double ref, double tol)
{
    const double ratio = sim / ref;
    return std::fabs(1.0 - ratio) > tol && std::fabs(sim) >= 1e-100 && std::fabs(ref) >= 1e-10;
}

double interpolateReference(const std::vector<double>& t, const std::vector<double>& v, double x)
{
    if (t.empty()) return 0.0;
    if (x < t.front()) return v.front();
    if (x >= t.back()) return v.back();
    if (t.size() == 1) return v.front();   // only a NaN x gets here
    // i with t[i] < x <= t[i+1] (i = 0 when x == t[0]). Times out of order, or a NaN x, can
    // leave the search at the end: i stays on the last segment rather than read past it.
    auto it = std::lower_bound(t.begin(), t.end(), x);
    std::size_t k = static_cast<std::size_t>(it - t.begin());
    std::size_t i = std::min(k == 0 ? std::size_t{0} : k - 1, t.size() - 2);
    return v[i] + (x - t[i]) * (v[i + 1] - v[i]) / (t[i + 1] - t[i]);
}

namespace {

using Table = std::vector<std::vector<double>>;

bool readDataFile(const std::string& path, Table& rows, std::string& error)
{
    std::ifstream in(path);
    if (!in) {
        error = "cannot open reference data '" + path + "'";
        return false;
    }
    std::string line;
    while (std::getline(in, line)) {
        if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
        std::vector<double> row;
        std::stringstream ss(line);
        std::string field;
        while (std::getline(ss, field, ',')) row.push_back(std::strtod(field.c_str(), nullptr));
        rows.push_back(std::move(row));
    }
    return true;
}

bool referenceColumn(const Table& rows, int timeCol, int valueCol, std::vector<double>& t,
                     std::vector<double>& v, std::string& error)
{
    if (timeCol < 0 || valueCol < 0) {
        error = "invalid time/value column";
        return false;
    }
    std::vector<std::pair<double, double>> pts;
    for (const auto& r : rows) {
        if (static_cast<int>(r.size()) <= std::max(timeCol, valueCol)) {
            error = "reference file has too few columns";
            return false;
        }
        pts.emplace_back(r[timeCol], r[valueCol]);
    }
    bool increasing = true, decreasing = true;
    for (std::size_t i = 1; i < pts.size(); ++i) {
        increasing = increasing && pts[i].first > pts[i - 1].first;
        decreasing = decreasing && pts[i].first < pts[i - 1].first;
    }
    if (decreasing && !increasing) std::reverse(pts.begin(), pts.end());
    else if (!increasing) std::stable_sort(pts.begin(), pts.end(), [](auto& a, auto& b) { return a.first < b.first; });
    for (std::size_t i = 1; i < pts.size(); ++i)
        if (!(pts[i].first > pts[i - 1].first)) {
            error = "reference times are not strictly increasing (repeated time)";
            return false;
        }
    t.clear();
    v.clear();
    for (auto& [a, b] : pts) {
        t.push_back(a);
        v.push_back(b);
    }
    return true;
}

struct Extracted {
    std::vector<double> time;
    std::vector<double> data;
};

// Runs the model from its start to its stop time: compiled on the first call, reset and run
// again on later ones (the determinism check compares the two).
bool runOnce(System& root, std::optional<Simulation>& sim, std::string& error)
{
    if (!sim) {
        Result<Simulation> compiled = compile(root);
        if (!compiled) {
            error = describe(compiled.status());
            return false;
        }
        sim.emplace(std::move(*compiled));
    } else {
        sim->reset();
    }
    const Status status = sim->run();
    if (!status) {
        error = "simulation failed: " + describe(status);
        return false;
    }
    return true;
}

bool extract(System& root, const std::string& name, Extracted& out, std::string& error)
{
    const Result<VariableRef> variable = resolveVariable(root, name);
    if (!variable) {
        error = describe(variable.status());
        return false;
    }
    const Port* port = variable->port;
    const int slot = variable->slot;
    const Node* n = port->node();
    if (!n || !n->logOwner || n->logData.empty()) {
        error = "variable '" + name + "' is not logged";
        return false;
    }
    out.time = n->logOwner->logTime();
    out.data = loggedData(*port, slot, out.time.size());
    return true;
}

void compare(const std::vector<double>& sim, const std::vector<double>& ref,
             const std::vector<double>& time, VariableCheck& check)
{
    if (sim.size() != ref.size()) {
        check.error = "length differs: " + std::to_string(sim.size()) + " simulated vs " +
                      std::to_string(ref.size()) + " reference samples";
        check.passed = false;
        return;
    }
    check.passed = true;
    for (std::size_t i = 0; i < sim.size(); ++i) {
        const bool checked = std::fabs(sim[i]) >= 1e-100 && std::fabs(ref[i]) >= 1e-10;
        const double dev = std::fabs(1.0 - sim[i] / ref[i]);
        if (checked && dev > check.worstDeviation) {
            check.worstDeviation = dev;
            check.worstTime = i < time.size() ? time[i] : 0.0;
        }
        if (sampleFails(sim[i], ref[i], check.tolerance)) {
            check.passed = false;
            ++check.failedSamples;
        }
    }
}

std::string resolvePath(const fs::path& base, const std::string& rel, const std::string& fallback)
{
    std::string r = rel.empty() ? fallback : rel;
    return (base / r).lexically_normal().string();
}

void validateV2(pugi::xml_node validation, const fs::path& dir, const std::string& stem,
                ValidationReport& report)
{
    report.modelPath = resolvePath(dir, validation.child_value("modelfile"), stem + ".hmf");
    const std::string dataPath = resolvePath(dir, validation.child_value("hvdfile"), stem + ".hvd");
    LoadedModel model = loadHmfFile(report.modelPath);
    if (model.hasErrors()) {
        report.error = "model could not be loaded: " + model.firstError();
        return;
    }
    Table rows;
    if (!readDataFile(dataPath, rows, report.error)) return;
    System& root = *model.root;
    std::optional<Simulation> sim;
    std::string err;
    if (!runOnce(root, sim, err)) {
        report.error = err;
        return;
    }
    std::vector<std::pair<std::string, Extracted>> first;
    for (pugi::xml_node var : validation.children("variable")) {
        Extracted e;
        std::string name = var.attribute("name").as_string();
        if (!extract(root, name, e, err)) e.time.clear();
        first.emplace_back(name, std::move(e));
    }
    // Determinism: the same loaded model simulated again must give the same results.
    if (!runOnce(root, sim, err)) {
        report.error = "second run: " + err;
        return;
    }
    const std::vector<double>* timeBase = first.empty() ? nullptr : &first.front().second.time;
    std::size_t idx = 0;
    for (pugi::xml_node var : validation.children("variable")) {
        VariableCheck check;
        check.name = var.attribute("name").as_string();
        const char* tolText = var.child_value("tolerance");
        check.tolerance = *tolText ? std::strtod(tolText, nullptr) : 0.01;
        const int timeCol = *var.child_value("timecolumn") ? std::atoi(var.child_value("timecolumn")) : -1;
        const int valueCol = *var.child_value("column") ? std::atoi(var.child_value("column")) : -1;
        Extracted& e = first[idx++].second;
        Extracted again;
        std::string xerr;
        if (e.time.empty() && !extract(root, check.name, again, xerr)) {
            check.error = xerr;
            report.variables.push_back(check);
            continue;
        }
        if (!extract(root, check.name, again, xerr)) {
            check.error = xerr;
            report.variables.push_back(check);
            continue;
        }
        std::vector<double> rt, rv;
        if (!referenceColumn(rows, timeCol, valueCol, rt, rv, check.error)) {
            report.variables.push_back(check);
            continue;
        }
        std::vector<double> ref(timeBase->size());
        for (std::size_t i = 0; i < ref.size(); ++i) ref[i] = interpolateReference(rt, rv, (*timeBase)[i]);
        compare(e.data, ref, *timeBase, check);
        if (check.passed) {
            VariableCheck det = check;
            det.worstDeviation = 0.0;
            compare(again.data, e.data, *timeBase, det);
            VariableCheck detTime = check;
            detTime.tolerance = 0.001;
            compare(again.time, e.time, *timeBase, detTime);
            if (!det.passed || !detTime.passed) {
                check.passed = false;
                check.error = "not deterministic: a second run gave different results";
            }
        }
        report.variables.push_back(check);
    }
}

void validateV1(pugi::xml_node validation, const fs::path& dir, const std::string& stem,
                ValidationReport& report)
{
    report.modelPath = resolvePath(dir, validation.child_value("modelfile"), stem + ".hmf");
    for (pugi::xml_node comp : validation.children("component")) {
        for (pugi::xml_node port : comp.children("port")) {
            for (pugi::xml_node var : port.children("variable")) {
                VariableCheck check;
                check.name = std::string(comp.attribute("name").as_string()) + "#" +
                             port.attribute("name").as_string() + "#" + var.attribute("name").as_string();
                const char* tolText = var.child_value("tolerance");
                check.tolerance = *tolText ? std::strtod(tolText, nullptr) : 0.01;
                std::string csv = var.child_value("csvfile");
                if (csv.empty()) csv = port.child_value("csvfile");
                const std::string dataPath = resolvePath(dir, csv, stem + ".csv");
                const char* colText = var.child_value("column");
                const int column = *colText ? std::atoi(colText) : 1;
                Table rows;
                std::vector<double> rt, rv;
                if (!readDataFile(dataPath, rows, check.error) ||
                    !referenceColumn(rows, 0, column, rt, rv, check.error)) {
                    report.variables.push_back(check);
                    continue;
                }
                LoadedModel model = loadHmfFile(report.modelPath);
                if (model.hasErrors()) {
                    report.error = "model could not be loaded: " + model.firstError();
                    return;
                }
                System& root = *model.root;
                std::optional<Simulation> sim;
                std::string err;
                Extracted e, again;
                // Variables of the root system only (no subsystem paths) in hvc 0.1.
                if (!runOnce(root, sim, err) || !extract(root, check.name, e, err)) {
                    check.error = err;
                    report.variables.push_back(check);
                    continue;
                }
                if (!runOnce(root, sim, err) || !extract(root, check.name, again, err)) {
                    check.error = "second run: " + err;
                    report.variables.push_back(check);
                    continue;
                }
                std::vector<double> ref(e.time.size());
                for (std::size_t i = 0; i < ref.size(); ++i) ref[i] = interpolateReference(rt, rv, e.time[i]);
                compare(e.data, ref, e.time, check);
                if (check.passed) {
                    VariableCheck det = check;
                    compare(again.data, e.data, e.time, det);
                    if (!det.passed) {
                        check.passed = false;
                        check.error = "not deterministic: a second run gave different results";
                    }
                }
                report.variables.push_back(check);
            }
        }
    }
}

} // namespace

ValidationReport validateHvc(const std::string& hvcPath)
{
    ValidationReport report;
    report.hvcPath = hvcPath;
    pugi::xml_document doc;
    pugi::xml_parse_result parsed = doc.load_file(hvcPath.c_str());
    if (!parsed) {
        report.error = hvcPath + ": cannot read validation file: " + parsed.description();
        return report;
    }
    pugi::xml_node top = doc.child("hopsanvalidationconfiguration");
    if (!top) {
        report.error = hvcPath + ": root element is not <hopsanvalidationconfiguration>";
        return report;
    }
    const std::string version = top.attribute("hvcversion").as_string();
    const fs::path dir = fs::path(hvcPath).parent_path();
    const std::string stem = fs::path(hvcPath).stem().string();
    for (pugi::xml_node validation : top.children("validation")) {
        if (version == "0.2") validateV2(validation, dir, stem, report);
        else if (version == "0.1") validateV1(validation, dir, stem, report);
        else report.error = hvcPath + ": unsupported hvcversion '" + version + "'";
        if (!report.error.empty() || report.failed() > 0) break;
    }
    return report;
}

} // namespace tlmhub
