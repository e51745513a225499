// Round trips: a part of a model exported as an FMU with `tlmhub-cli fmu`, imported back into
// the rest of the model through an FMI wrapper component, run with `tlmhub-cli run`, must give
// the whole model's results. The parts are cut from the models at test time (the shared
// Position Servo is read in place).
#include "core/ComponentFactory.h"
#include "core/System.h"
#include "core/Validation.h"
#include "core/hmf/HmfLoader.h"
#include "core/hmf/HmfSaver.h"

#include <gtest/gtest.h>
#include <pugixml.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

using namespace tlmhub;
namespace fs = std::filesystem;

namespace {

struct CommandOutput {
    int exitCode = -1;
    std::string text;
};

CommandOutput runCommand(const std::string& command)
{
    CommandOutput out;
    FILE* pipe = popen((command + " 2>&1").c_str(), "r");
    if (!pipe) return out;
    std::array<char, 4096> buffer{};
    while (std::fgets(buffer.data(), buffer.size(), pipe)) out.text += buffer.data();
    const int status = pclose(pipe);
    out.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return out;
}

// For the shell (the test's own paths hold no quotes).
std::string quoted(const fs::path& path)
{
    std::string text(1, '\'');
    text += path.string();
    text += '\'';
    return text;
}

fs::path freshDirectory(const std::string& name)
{
    const fs::path dir = fs::temp_directory_path() / ("tlmhub-fmu-roundtrip-" + name + "-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

// Columns of a `tlmhub-cli run --csv` file by header name.
std::map<std::string, std::vector<double>> readCsv(const fs::path& path)
{
    std::ifstream in(path);
    std::string line;
    std::vector<std::string> names;
    std::map<std::string, std::vector<double>> columns;
    if (!std::getline(in, line)) return columns;
    std::stringstream header(line);
    for (std::string name; std::getline(header, name, ',');) names.push_back(name);
    while (std::getline(in, line)) {
        std::stringstream row(line);
        std::string cell;
        for (std::size_t i = 0; i < names.size() && std::getline(row, cell, ','); ++i)
            columns[names[i]].push_back(std::stod(cell));
    }
    return columns;
}

std::map<std::string, std::vector<double>> runModel(const fs::path& model, const fs::path& csv)
{
    const CommandOutput run = runCommand(quoted(TLMHUB_CLI) + " run " + quoted(model) + " --csv " + quoted(csv));
    EXPECT_EQ(run.exitCode, 0) << run.text;
    return readCsv(csv);
}

void exportFmu(const fs::path& model, const fs::path& fmu)
{
    const CommandOutput exported =
        runCommand(quoted(TLMHUB_CLI) + " fmu " + quoted(model) + " -o " + quoted(fmu));
    ASSERT_EQ(exported.exitCode, 0) << exported.text;
    ASSERT_TRUE(fs::exists(fmu)) << exported.text;
}

void add(System& s, const std::string& type, const std::string& name)
{
    auto component = ComponentFactory::instance().create(type);
    ASSERT_TRUE(component) << type;
    component->setNameRaw(name);
    s.addComponent(std::move(component));
}

void connect(System& s, const std::string& a, const std::string& pa, const std::string& b, const std::string& pb)
{
    const Status status = s.connect(a, pa, b, pb);
    ASSERT_TRUE(status) << describe(status);
}

void setParameter(System& s, const std::string& component, const std::string& name, const std::string& value)
{
    Parameter* parameter = s.component(component)->parameters().find(name);
    ASSERT_TRUE(parameter) << component << "." << name;
    parameter->value = value;
}

std::unique_ptr<System> load(const fs::path& path)
{
    LoadedModel model = loadHmfFile(path.string());
    EXPECT_FALSE(model.hasErrors()) << model.firstError();
    return std::move(model.root);
}

void keepOnly(System& s, const std::vector<std::string>& kept)
{
    std::vector<std::string> removed;
    for (const Component* c : s.componentsInOrder())
        if (std::find(kept.begin(), kept.end(), c->name()) == kept.end()) removed.push_back(c->name());
    for (const std::string& name : removed) ASSERT_TRUE(s.removeComponent(name)) << name;
}

// The model text with an FMU wrapper component added: the wrapper's ports come from the FMU
// when the model is read, so it is added to the file, not to the System.
std::string withWrapper(const System& root, const std::string& wrapperType, const std::string& name,
                        const std::string& fmuFile,
                        const std::vector<std::array<std::string, 4>>& connections)
{
    pugi::xml_document document;
    document.load_string(saveHmfString(root).c_str());
    pugi::xml_node system = document.child("hopsanmodelfile").child("system");
    pugi::xml_node component = system.child("objects").append_child("component");
    component.append_attribute("typename") = wrapperType.c_str();
    component.append_attribute("name") = name.c_str();
    pugi::xml_node parameter = component.append_child("parameters").append_child("parameter");
    parameter.append_attribute("name") = "path";
    parameter.append_attribute("value") = fmuFile.c_str();
    parameter.append_attribute("type") = "string";
    pugi::xml_node links = system.child("connections");
    if (!links) links = system.append_child("connections");
    for (const auto& [startComponent, startPort, endComponent, endPort] : connections) {
        pugi::xml_node link = links.append_child("connect");
        link.append_attribute("startcomponent") = startComponent.c_str();
        link.append_attribute("startport") = startPort.c_str();
        link.append_attribute("endcomponent") = endComponent.c_str();
        link.append_attribute("endport") = endPort.c_str();
    }
    std::ostringstream text;
    document.save(text);
    return text.str();
}

void writeText(const fs::path& path, const std::string& text)
{
    std::ofstream(path) << text;
}

struct Deviation {
    double worst = 0.0;
    std::size_t failedSamples = 0;
};

// The .hvc rule (core/Validation.h) applied sample by sample at equal times.
Deviation compare(const std::vector<double>& sim, const std::vector<double>& ref, double tolerance)
{
    Deviation d;
    EXPECT_EQ(sim.size(), ref.size());
    for (std::size_t i = 0; i < std::min(sim.size(), ref.size()); ++i) {
        if (sampleFails(sim[i], ref[i], tolerance)) ++d.failedSamples;
        if (std::abs(ref[i]) >= 1e-10) d.worst = std::max(d.worst, std::abs(1.0 - sim[i] / ref[i]));
    }
    return d;
}

const fs::path kServo = fs::path(TLMHUB_SHARED_DIR) / "hopsan-models/Example Models/Position Servo.hmf";
const std::vector<std::string> kController = {"Step", "Subtract", "GainP", "Integrator", "GainI", "Add"};

} // namespace

TEST(FmuRoundTrip, PositionServoControllerAsAnFmuGivesTheWholeModelsResults)
{
    ASSERT_TRUE(fs::exists(kServo)) << "missing shared model " << kServo;
    const fs::path dir = freshDirectory("servo");

    // The controller alone: position in, valve command out.
    std::unique_ptr<System> controller = load(kServo);
    ASSERT_TRUE(controller);
    keepOnly(*controller, kController);
    add(*controller, "SignalInputInterface", "x");
    add(*controller, "SignalOutputInterface", "u");
    connect(*controller, "x", "out", "Subtract", "in2");
    connect(*controller, "Add", "out", "u", "in");
    ASSERT_TRUE(saveHmfFile(*controller, (dir / "controller.hmf").string()));
    exportFmu(dir / "controller.hmf", dir / "controller.fmu");

    // The rest of the servo, with the FMU in the controller's place.
    std::unique_ptr<System> plant = load(kServo);
    ASSERT_TRUE(plant);
    for (const std::string& name : kController) ASSERT_TRUE(plant->removeComponent(name)) << name;
    writeText(dir / "plant.hmf", withWrapper(*plant, "FMIWrapper", "Controller", "controller.fmu",
                                             {{"Position_Sensor", "out", "Controller", "x"},
                                              {"Controller", "u", "4_3_Servo_Valve", "in"}}));

    const auto whole = runModel(kServo, dir / "whole.csv");
    const auto split = runModel(dir / "plant.hmf", dir / "plant.csv");
    ASSERT_EQ(split.at("time"), whole.at("time"));
    // The valve command comes out of the FMU.
    ASSERT_TRUE(split.count("Controller#u#Value"));
    EXPECT_EQ(compare(split.at("Controller#u#Value"), whole.at("Add#out#Value"), 0.01).failedSamples, 0u);
    // The variables Position Servo.hvc checks that remain in the plant, at its tolerance.
    for (const std::string name : {"Position_Sensor#out#Value", "4_3_Servo_Valve#xv#Value", "Pressure_Relief_Valve#xv#Value"}) {
        ASSERT_TRUE(split.count(name) && whole.count(name)) << name;
        const Deviation d = compare(split.at(name), whole.at(name), 0.01);
        EXPECT_EQ(d.failedSamples, 0u) << name << ": worst |1 - split/whole| " << d.worst;
        RecordProperty(name, std::to_string(d.worst));
        std::printf("%s: worst |1 - split/whole| = %.3g\n", name.c_str(), d.worst);
    }
    fs::remove_all(dir);
}

TEST(FmuRoundTrip, AHydraulicPartBehindATlmPortGivesTheWholeModelsResults)
{
    const fs::path dir = freshDirectory("hydraulic");
    // Whole: 10 MPa source -> orifice -> 1 l volume -> orifice -> tank.
    auto buildUpstream = [](System& s) {
        add(s, "HydraulicPressureSourceC", "Source");
        add(s, "HydraulicLaminarOrifice", "Inlet");
        add(s, "HydraulicVolume", "Volume");
        connect(s, "Source", "P1", "Inlet", "P1");
        connect(s, "Inlet", "P2", "Volume", "P1");
        setParameter(s, "Source", "p#Value", "1e7");
        setParameter(s, "Inlet", "Kc#Value", "2e-11");
        setParameter(s, "Volume", "V", "1e-3");
    };
    auto buildDownstream = [](System& s, const std::string& from, const std::string& port) {
        add(s, "HydraulicLaminarOrifice", "Outlet");
        add(s, "HydraulicTankC", "Tank");
        connect(s, from, port, "Outlet", "P1");
        connect(s, "Outlet", "P2", "Tank", "P1");
        setParameter(s, "Outlet", "Kc#Value", "1e-11");
    };
    auto settings = [](System& s) {
        s.setNameRaw("Hydraulic_Round_Trip");
        s.startTime = 0.0;
        s.stopTime = 0.2;
        s.setTimestep(1e-4);
        s.desiredTimestep = 1e-4;
    };
    System whole;
    settings(whole);
    buildUpstream(whole);
    buildDownstream(whole, "Volume", "P2");
    ASSERT_TRUE(saveHmfFile(whole, (dir / "whole.hmf").string()));

    // The outlet and the tank behind a C-type interface: the FMU takes the volume's wave
    // variable and impedance and gives back pressure and flow.
    System outlet;
    settings(outlet);
    add(outlet, "HydraulicInterfaceC", "P1");
    buildDownstream(outlet, "P1", "P1");
    ASSERT_TRUE(saveHmfFile(outlet, (dir / "outlet.hmf").string()));
    exportFmu(dir / "outlet.hmf", dir / "outlet.fmu");

    System upstream;
    settings(upstream);
    buildUpstream(upstream);
    writeText(dir / "plant.hmf", withWrapper(upstream, "FMIWrapperQ", "Outlet", "outlet.fmu",
                                             {{"Volume", "P2", "Outlet", "P1"}}));

    const auto reference = runModel(dir / "whole.hmf", dir / "whole.csv");
    const auto split = runModel(dir / "plant.hmf", dir / "plant.csv");
    ASSERT_EQ(split.at("time"), reference.at("time"));
    for (const std::string name : {"Volume#P1#Pressure", "Volume#P2#Pressure", "Volume#P2#Flow", "Inlet#P1#Flow"}) {
        ASSERT_TRUE(split.count(name) && reference.count(name)) << name;
        const Deviation d = compare(split.at(name), reference.at(name), 0.01);
        EXPECT_EQ(d.failedSamples, 0u) << name << ": worst |1 - split/whole| " << d.worst;
        std::printf("%s: worst |1 - split/whole| = %.3g\n", name.c_str(), d.worst);
    }
    fs::remove_all(dir);
}
