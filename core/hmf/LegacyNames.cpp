#include "core/hmf/LegacyNames.h"

#include <cstdlib>
#include <map>
#include <utility>
#include <vector>

namespace tlmhub::legacy {

namespace {

struct Rename {
    const char* type;   // "*" = any type
    const char* from;
    const char* to;
};

// Obsolete and misspelt type names.
const std::map<std::string, std::string>& typeAliases()
{
    static const std::map<std::string, std::string> m = {
        {"SignalSource", "SignalConstant"},
        {"MechanicRotationalInertiaWithCoulumbFriction", "MechanicRotationalInertiaWithCoulombFriction"},
        {"MechanicTranslationalMassWithCoulumbFriction", "MechanicTranslationalMassWithCoulombFriction"},
    };
    return m;
}

// Port renames applied by Hopsan's GUI to files its core refuses (pre-0.6.0 / early 0.6.x).
const std::vector<Rename>& portRenames()
{
    static const std::vector<Rename> v = {
        {"SignalConstant", "out", "y"},
        {"SignalSource", "out", "y"},
        {"MechanicForceTransformer", "in", "F"},
        {"MechanicTranslationalMassWithCoulombFriction", "Pfs", "f_s"},
        {"MechanicTranslationalMassWithCoulombFriction", "Pfk", "f_k"},
        {"MechanicVelocityTransformer", "vin", "v"},
        {"MechanicVelocityTransformer", "xin", "x"},
        {"MechanicTorqueTransformer", "in", "T"},
        {"HydraulicPressureSourceQ", "In", "p"},
        {"HydraulicPressureSourceQ", "in", "p"},
        {"HydraulicPressureSourceC", "In", "p"},
        {"HydraulicPressureSourceC", "in", "p"},
        {"HydraulicFlowSourceQ", "in", "q"},
        // Renamed outputs/inputs of aero and mechanic types (matched by position and default
        // value against the current ports).
        {"AeroAtmosphere", "rho", "rhoa"},
        {"AeroAtmosphere", "T", "Ta"},
        {"AeroAtmosphere", "Tav", "Ta"},
        {"AeroCombustionChamberMono", "p0", "pa"},
        {"AeroCombustionChamberMono", "pt", "pc"},
        {"AeroCombustionChamberMono", "Tt", "Tc"},
        {"AeroCombustionChamberMono", "mc", "rhogas"},
        {"MechanicThetaSource", "win", "omega"},
    };
    return v;
}

// Parameter renames applied by the GUI to refused files, after the '::' rewrite.
const std::vector<Rename>& parameterRenames()
{
    static const std::vector<Rename> v = {
        {"HydraulicLaminarOrifice", "K_c", "Kc"},
        {"SignalConstant", "Value", "y#Value"},
        {"SignalConstant", "y", "y#Value"},
        {"SignalConstant", "out#Value", "y#Value"},
        {"HydraulicVolume3", "Be", "Beta_e"},
        {"HydraulicVolume3", "a", "alpha"},
    };
    return v;
}

// "0.6.x_r5500" -> 5500; -1 if there is no revision.
long revisionOf(const std::string& v)
{
    auto pos = v.find("_r");
    if (pos == std::string::npos) return -1;
    return std::strtol(v.c_str() + pos + 2, nullptr, 10);
}

// First two numeric fields (generation, major); non-numeric fields read as -1.
std::pair<long, long> generationMajor(const std::string& v)
{
    long f[2] = {-1, -1};
    std::size_t start = 0;
    for (int i = 0; i < 2; ++i) {
        std::size_t end = v.find('.', start);
        std::string field = v.substr(start, end == std::string::npos ? std::string::npos : end - start);
        char* e = nullptr;
        long n = std::strtol(field.c_str(), &e, 10);
        f[i] = (e && *e == '\0' && !field.empty()) ? n : -1;
        if (end == std::string::npos) break;
        start = end + 1;
    }
    return {f[0], f[1]};
}

} // namespace

bool CoreVersion::usesOldParameterNames() const
{
    if (text.find("0.6.x_r") != std::string::npos) return true;
    auto [gen, major] = generationMajor(text);
    if (gen < 0) return true;
    if (gen == 0 && major < 6) return true;
    return false;
}

bool CoreVersion::refusedByHopsanCore() const
{
    if (text.find("0.6.x_r") != std::string::npos) return revisionOf(text) < 5500;
    auto [gen, major] = generationMajor(text);
    if (gen < 0) return true;
    return gen == 0 && major < 6;
}

std::string currentTypeName(const std::string& typeName)
{
    auto it = typeAliases().find(typeName);
    return it == typeAliases().end() ? typeName : it->second;
}

std::string currentPortName(const std::string& typeName, const std::string& portName,
                            bool fullRenames)
{
    if (!fullRenames) return portName;
    for (const Rename& r : portRenames())
        if (typeName == r.type && portName == r.from) return r.to;
    return portName;
}

std::string currentParameterName(const std::string& typeName, const std::string& parameterName,
                                 const CoreVersion& version)
{
    std::string name = parameterName;
    if (!version.usesOldParameterNames()) return name;
    // The core loader's rewrite.
    for (std::size_t pos; (pos = name.find("::")) != std::string::npos;) name.replace(pos, 2, "#");
    if (name == "sigma^2") name = "std_dev";
    const bool full = version.refusedByHopsanCore();
    if (full) {
        // The GUI's full rename of variable names (what the author meant).
        static const std::pair<const char*, const char*> vars[] = {
            {"Angular Velocity", "AngularVelocity"},
            {"Equivalent Inertia", "EquivalentInertia"},
            {"CharImp", "CharImpedance"},
        };
        for (const auto& [from, to] : vars) {
            auto pos = name.find(from);
            if (pos != std::string::npos && name.find(to) == std::string::npos)
                name.replace(pos, std::string(from).size(), to);
        }
    }
    std::string cleaned;
    for (char c : name) {
        if (c == ',' || c == '.') continue;
        cleaned += (c == ' ') ? '_' : c;
    }
    name = cleaned;
    if (full) {
        for (const Rename& r : parameterRenames())
            if (typeName == r.type && name == r.from) return r.to;
        // Start values of renamed ports follow the port: "<old>#Var" -> "<new>#Var".
        const auto hash = name.find('#');
        if (hash != std::string::npos) {
            const std::string port = name.substr(0, hash);
            const std::string renamed = currentPortName(typeName, port, true);
            if (renamed != port) return renamed + name.substr(hash);
        }
    }
    return name;
}

} // namespace tlmhub::legacy
