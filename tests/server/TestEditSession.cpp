#include "TestFiles.h"

#include "server/edit/EditSession.h"
#include "server/protocol/SchemaValidator.h"

#include <gtest/gtest.h>
#include <pugixml.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace tlmhub::server;
using tlmhub::test::readFile;
using nlohmann::json;

namespace {

const std::string kModels = TLMHUB_SOURCE_DIR "/../shared/hopsan-models/Example Models/";

// A session with Position Servo open (root system Position_Servo, 20 components).
EditSession openServo()
{
    EditSession session;
    std::string error;
    EXPECT_TRUE(session.openHmf(readFile(kModels + "Position Servo.hmf"), "Position Servo", error)) << error;
    return session;
}

const json* findByName(const json& list, const std::string& name)
{
    for (const json& item : list)
        if (item.at("name") == name) return &item;
    return nullptr;
}

const json* findConnection(const json& system, const std::string& a, const std::string& pa,
                           const std::string& b, const std::string& pb)
{
    for (const json& c : system.at("connections")) {
        const json& f = c.at("from");
        const json& t = c.at("to");
        if ((f.at("component") == a && f.at("port") == pa && t.at("component") == b && t.at("port") == pb) ||
            (f.at("component") == b && f.at("port") == pb && t.at("component") == a && t.at("port") == pa))
            return &c;
    }
    return nullptr;
}

json rootSystem(const EditSession& s) { return json(s.model()).at("system"); }

// Checks the reply data of a request type against its x-replies definition.
void expectReplyShape(const std::string& requestType, const EditSession::Result& r)
{
    ASSERT_TRUE(r.ok) << r.code << ": " << r.message;
    const json reply = {{"id", 1}, {"type", "reply"}, {"ok", true}, {"data", r.data}};
    std::string error;
    EXPECT_TRUE(SchemaValidator::protocol().validateServerMessage(reply, requestType, error)) << error;
}

} // namespace

TEST(ModelJson, ListsEveryComponentWithPoseAndEveryConnectionWithPoints)
{
    const std::string hmf = readFile(kModels + "Position Servo.hmf");
    EditSession session = openServo();
    const json model = json(session.model());
    std::string error;
    EXPECT_TRUE(SchemaValidator::protocol().validate("Model", model, error)) << error;
    EXPECT_EQ(model.at("name"), "Position Servo");

    // Compare with the file itself: every component and connection, every pose.
    pugi::xml_document doc;
    ASSERT_TRUE(doc.load_string(hmf.c_str()));
    const pugi::xml_node root = doc.child("hopsanmodelfile").child("system");
    const json& system = model.at("system");
    EXPECT_EQ(system.at("name"), "Position_Servo");
    EXPECT_EQ(system.at("simulation").at("stop"), 3.0);
    std::size_t components = 0;
    for (pugi::xml_node c : root.child("objects").children("component")) {
        ++components;
        const json* jc = findByName(system.at("components"), c.attribute("name").as_string());
        ASSERT_NE(jc, nullptr) << c.attribute("name").as_string();
        const pugi::xml_node pose = c.child("hopsangui").child("pose");
        EXPECT_DOUBLE_EQ(jc->at("pose").at("x").get<double>(), pose.attribute("x").as_double());
        EXPECT_DOUBLE_EQ(jc->at("pose").at("y").get<double>(), pose.attribute("y").as_double());
        EXPECT_DOUBLE_EQ(jc->at("pose").at("angle").get<double>(), pose.attribute("a").as_double());
    }
    EXPECT_EQ(components, 20u);
    EXPECT_EQ(system.at("components").size(), components);
    std::size_t connections = 0;
    for (pugi::xml_node c : root.child("connections").children("connect")) {
        ++connections;
        const json* jc = findConnection(system, c.attribute("startcomponent").as_string(), c.attribute("startport").as_string(),
                                        c.attribute("endcomponent").as_string(), c.attribute("endport").as_string());
        ASSERT_NE(jc, nullptr) << c.attribute("startcomponent").as_string() << "." << c.attribute("startport").as_string();
        const auto coordinates = c.child("hopsangui").child("coordinates").children("coordinate");
        EXPECT_EQ(jc->at("points").size(), static_cast<std::size_t>(std::distance(coordinates.begin(), coordinates.end())));
    }
    EXPECT_EQ(connections, 24u);
    EXPECT_EQ(system.at("connections").size(), connections);

    const json* valve = findByName(system.at("components"), "Hydraulic_Volume_Multi_Port");
    EXPECT_EQ(valve->at("pose").at("angle"), 90.0);
    EXPECT_EQ(valve->at("kind"), "C");
    const json* p1 = findByName(valve->at("ports"), "P1");
    EXPECT_EQ(p1->at("node_type"), "NodeHydraulic");
    EXPECT_EQ(p1->at("kind"), "power");
    EXPECT_TRUE(p1->at("multiport").get<bool>());
    EXPECT_TRUE(p1->at("connected").get<bool>());
    const json* massToCylinder = findConnection(system, "Mass", "P1", "Cylinder_C", "P3");
    ASSERT_NE(massToCylinder, nullptr);
    EXPECT_EQ(massToCylinder->at("points")[0], json::array({2636.5, 2422.0}));
    const json* mass = findByName(system.at("components"), "Mass");
    EXPECT_EQ(findByName(mass->at("parameters"), "m")->at("value"), "100");
    EXPECT_EQ(findByName(mass->at("parameters"), "m")->at("unit"), "kg");
}

TEST(ModelJson, SubsystemsNestWithTheirOwnComponentsAndSystemPorts)
{
    EditSession session;
    std::string error;
    ASSERT_TRUE(session.openHmf(readFile(kModels + "Sub System Example.hmf"), "Sub", error)) << error;
    const json model = json(session.model());
    EXPECT_TRUE(SchemaValidator::protocol().validate("Model", model, error)) << error;
    const json* servo = findByName(model.at("system").at("components"), "Servo1");
    ASSERT_NE(servo, nullptr);
    EXPECT_EQ(servo->at("kind"), "system");
    EXPECT_EQ(servo->at("type"), "Subsystem");
    const json& inner = servo->at("system");
    EXPECT_FALSE(inner.contains("simulation"));
    EXPECT_NE(findByName(inner.at("components"), "Cylinder_C"), nullptr);
    EXPECT_NE(findConnection(inner, "Translational_Mass", "P1", "Cylinder_C", "P3"), nullptr);
    ASSERT_FALSE(inner.at("ports").empty());
    const json* port = findByName(inner.at("ports"), "Container_Port_3");
    ASSERT_NE(port, nullptr);
    EXPECT_EQ(port->at("pose").at("x"), 2597.0);
    EXPECT_EQ(port->at("pose").at("y"), 2333.8);
}

TEST(EditSession, AddsAComponentWithPose)
{
    EditSession session = openServo();
    const auto r = session.handle({{"id", 1}, {"type", "component.add"}, {"component_type", "HydraulicVolume"},
                                   {"pose", {{"x", 10.5}, {"y", -20}, {"angle", 90}, {"flipped", true}}}});
    expectReplyShape("component.add", r);
    const json& c = r.data.at("component");
    EXPECT_EQ(c.at("type"), "HydraulicVolume");
    EXPECT_EQ(c.at("kind"), "C");
    EXPECT_EQ(c.at("pose"), json({{"x", 10.5}, {"y", -20.0}, {"angle", 90.0}, {"flipped", true}}));
    const json system = rootSystem(session);
    EXPECT_EQ(system.at("components").size(), 21u);
    EXPECT_NE(findByName(system.at("components"), c.at("name").get<std::string>()), nullptr);
}

TEST(EditSession, PortKindsNameReadWriteAndBidirectionalSignalPorts)
{
    EditSession session = openServo();
    const auto r = session.handle({{"id", 1}, {"type", "component.add"}, {"component_type", "Signal2DReadWrite"}});
    expectReplyShape("component.add", r);
    const json& ports = r.data.at("component").at("ports");
    EXPECT_EQ(findByName(ports, "P2d")->at("kind"), "bidirectional");
    EXPECT_EQ(findByName(ports, "P2d")->at("node_type"), "NodeSignal2D");
    EXPECT_EQ(findByName(ports, "read")->at("kind"), "write");
    EXPECT_EQ(findByName(ports, "write")->at("kind"), "read");
}

TEST(EditSession, AddedNamesAreMadeUnique)
{
    EditSession session = openServo();
    const auto r = session.handle({{"id", 1}, {"type", "component.add"}, {"component_type", "MechanicTranslationalMass"},
                                   {"name", "Mass"}});
    ASSERT_TRUE(r.ok) << r.message;
    EXPECT_EQ(r.data["component"]["name"], "Mass_1");
    EXPECT_EQ(r.data["component"]["pose"], json({{"x", 0.0}, {"y", 0.0}, {"angle", 0.0}, {"flipped", false}}));
}

TEST(EditSession, UnknownComponentTypeIsNamed)
{
    EditSession session = openServo();
    const auto r = session.handle({{"id", 1}, {"type", "component.add"}, {"component_type", "HydraulicTeapot"}});
    EXPECT_FALSE(r.ok);
    EXPECT_EQ(r.code, "unknown_component_type");
    EXPECT_NE(r.message.find("HydraulicTeapot"), std::string::npos);
    EXPECT_EQ(rootSystem(session).at("components").size(), 20u);
}

TEST(EditSession, RenameIsMadeUniqueAndConnectionsFollow)
{
    EditSession session = openServo();
    const auto r = session.handle({{"id", 1}, {"type", "component.rename"}, {"name", "Mass"}, {"new_name", "Sink"}});
    expectReplyShape("component.rename", r);
    const std::string actual = r.data.at("name").get<std::string>();
    EXPECT_NE(actual, "Sink");
    EXPECT_EQ(actual.rfind("Sink_", 0), 0u) << actual;
    const json system = rootSystem(session);
    EXPECT_EQ(findByName(system.at("components"), "Mass"), nullptr);
    EXPECT_NE(findByName(system.at("components"), actual), nullptr);
    const json* c = findConnection(system, actual, "P1", "Cylinder_C", "P3");
    ASSERT_NE(c, nullptr);
    EXPECT_EQ(c->at("points").size(), 4u);   // the line's points moved with the name

    // Characters outside [A-Za-z0-9_] become '_'.
    const auto spaced = session.handle({{"id", 2}, {"type", "component.rename"}, {"name", actual}, {"new_name", "Big mass"}});
    EXPECT_EQ(spaced.data.at("name"), "Big_mass");
    const auto missing = session.handle({{"id", 3}, {"type", "component.rename"}, {"name", "Nobody"}, {"new_name", "X"}});
    EXPECT_EQ(missing.code, "not_found");
}

TEST(EditSession, IllegalConnectionGivesTheCoreReason)
{
    EditSession session = openServo();
    const auto r = session.handle({{"id", 1}, {"type", "connect"},
                                   {"from", {{"component", "Mass"}, {"port", "P2"}}},
                                   {"to", {{"component", "Tank_C"}, {"port", "P1"}}}});
    EXPECT_FALSE(r.ok);
    EXPECT_EQ(r.code, "illegal_connection");
    EXPECT_NE(r.message.find("Mass.P2"), std::string::npos) << r.message;
    EXPECT_NE(r.message.find("Tank_C.P1"), std::string::npos) << r.message;
    EXPECT_NE(r.message.find("node types differ"), std::string::npos) << r.message;

    const auto unknown = session.handle({{"id", 2}, {"type", "connect"},
                                         {"from", {{"component", "Mass"}, {"port", "P9"}}},
                                         {"to", {{"component", "Tank_C"}, {"port", "P1"}}}});
    EXPECT_EQ(unknown.code, "not_found");
}

TEST(EditSession, ConnectAndDisconnectWithLinePoints)
{
    EditSession session = openServo();
    session.handle({{"id", 1}, {"type", "component.add"}, {"component_type", "SignalSink"}, {"name", "Probe"}});
    const auto r = session.handle({{"id", 2}, {"type", "connect"},
                                   {"from", {{"component", "Step"}, {"port", "out"}}},
                                   {"to", {{"component", "Probe"}, {"port", "in"}}},
                                   {"points", {{1, 2}, {3, 2}}}});
    expectReplyShape("connect", r);
    EXPECT_EQ(r.data["connection"]["points"], json({{1.0, 2.0}, {3.0, 2.0}}));
    EXPECT_EQ(rootSystem(session).at("connections").size(), 25u);

    // The points are saved the way Hopsan saves them.
    EditSession reloaded;
    std::string error;
    ASSERT_TRUE(reloaded.openHmf(session.saveHmf(), "again", error)) << error;
    const json reloadedSystem = rootSystem(reloaded);
    const json* c = findConnection(reloadedSystem, "Step", "out", "Probe", "in");
    ASSERT_NE(c, nullptr);
    EXPECT_EQ(c->at("points"), json({{1.0, 2.0}, {3.0, 2.0}}));

    const auto d = session.handle({{"id", 3}, {"type", "disconnect"},
                                   {"from", {{"component", "Probe"}, {"port", "in"}}},
                                   {"to", {{"component", "Step"}, {"port", "out"}}}});
    expectReplyShape("disconnect", d);
    EXPECT_EQ(findConnection(rootSystem(session), "Step", "out", "Probe", "in"), nullptr);
    const auto again = session.handle({{"id", 4}, {"type", "disconnect"},
                                       {"from", {{"component", "Probe"}, {"port", "in"}}},
                                       {"to", {{"component", "Step"}, {"port", "out"}}}});
    EXPECT_EQ(again.code, "illegal_connection");
    EXPECT_NE(again.message.find("not connected"), std::string::npos) << again.message;
    const auto unknown = session.handle({{"id", 5}, {"type", "disconnect"},
                                         {"from", {{"component", "Probe"}, {"port", "nope"}}},
                                         {"to", {{"component", "Step"}, {"port", "out"}}}});
    EXPECT_EQ(unknown.code, "not_found");
}

TEST(EditSession, RouteReplacesALinesPointsAndTheyAreSavedAsHopsanSavesThem)
{
    EditSession session = openServo();
    const json loaded = rootSystem(session);
    const json* before = findConnection(loaded, "Mass", "P1", "Cylinder_C", "P3");
    ASSERT_NE(before, nullptr);
    const json from = before->at("from");
    const json to = before->at("to");
    const json points = {{10, 20}, {40, 20}, {40, 60}, {70, 60}};
    // Named from its "to" end: the reply gives the points in the order they were sent.
    const auto r = session.handle({{"id", 1}, {"type", "connection.route"}, {"from", to}, {"to", from},
                                   {"points", points}});
    expectReplyShape("connection.route", r);
    EXPECT_EQ(r.data["connection"]["points"], points);
    const json routed = rootSystem(session);
    const json* now = findConnection(routed, "Mass", "P1", "Cylinder_C", "P3");
    ASSERT_NE(now, nullptr);
    EXPECT_EQ(now->at("points"), json({{70, 60}, {40, 60}, {40, 20}, {10, 20}}));   // from -> to as listed

    // The file gets the coordinates and each segment's direction, as Hopsan writes them.
    const std::string hmf = session.saveHmf();
    pugi::xml_document doc;
    ASSERT_TRUE(doc.load_string(hmf.c_str()));
    bool found = false;
    for (const pugi::xpath_node& n : doc.select_nodes("//connect")) {
        const pugi::xml_node c = n.node();
        const std::string a = c.attribute("startcomponent").value();
        const std::string b = c.attribute("endcomponent").value();
        if (!((a == "Mass" && b == "Cylinder_C") || (a == "Cylinder_C" && b == "Mass"))) continue;
        found = true;
        std::vector<std::string> geometries;
        for (const pugi::xml_node g : c.child("hopsangui").child("geometries").children("geometry"))
            geometries.push_back(g.text().get());
        EXPECT_EQ(geometries, (std::vector<std::string>{"vertical", "horizontal", "vertical"}));
    }
    EXPECT_TRUE(found);
    EditSession reloaded;
    std::string error;
    ASSERT_TRUE(reloaded.openHmf(hmf, "again", error)) << error;
    const json reloadedSystem = rootSystem(reloaded);
    const json* again = findConnection(reloadedSystem, "Mass", "P1", "Cylinder_C", "P3");
    ASSERT_NE(again, nullptr);
    EXPECT_EQ(again->at("from"), now->at("from"));
    EXPECT_EQ(again->at("points"), now->at("points"));

    // No points: the line is drawn from port to port, and saved without coordinates.
    ASSERT_TRUE(session.handle({{"id", 2}, {"type", "connection.route"}, {"from", from}, {"to", to},
                                {"points", json::array()}}).ok);
    const json straightened = rootSystem(session);
    EXPECT_TRUE(findConnection(straightened, "Mass", "P1", "Cylinder_C", "P3")->at("points").empty());

    const auto unconnected = session.handle({{"id", 3}, {"type", "connection.route"},
                                             {"from", {{"component", "Mass"}, {"port", "P1"}}},
                                             {"to", {{"component", "Step"}, {"port", "out"}}},
                                             {"points", points}});
    EXPECT_EQ(unconnected.code, "not_found");
    EXPECT_NE(unconnected.message.find("not connected"), std::string::npos) << unconnected.message;
}

TEST(EditSession, RemoveDropsTheComponentAndItsConnections)
{
    EditSession session = openServo();
    const auto r = session.handle({{"id", 1}, {"type", "component.remove"}, {"name", "Mass"}});
    expectReplyShape("component.remove", r);
    const json system = rootSystem(session);
    EXPECT_EQ(system.at("components").size(), 19u);
    for (const json& c : system.at("connections")) {
        EXPECT_NE(c["from"]["component"], "Mass");
        EXPECT_NE(c["to"]["component"], "Mass");
    }
    EXPECT_EQ(system.at("connections").size(), 21u);   // Mass had three
    EXPECT_EQ(session.handle({{"id", 2}, {"type", "component.remove"}, {"name", "Mass"}}).code, "not_found");

    // A new component of the old name does not inherit the old connection's line points.
    session.handle({{"id", 3}, {"type", "component.add"}, {"component_type", "MechanicTranslationalMass"}, {"name", "Mass"}});
    const auto c = session.handle({{"id", 4}, {"type", "connect"},
                                   {"from", {{"component", "Mass"}, {"port", "P1"}}},
                                   {"to", {{"component", "Cylinder_C"}, {"port", "P3"}}}});
    ASSERT_TRUE(c.ok) << c.message;
    EXPECT_TRUE(c.data["connection"]["points"].empty());
}

TEST(EditSession, ParameterSetKeepsOldValueWhenEvaluationFails)
{
    EditSession session = openServo();
    const auto good = session.handle({{"id", 1}, {"type", "parameter.set"}, {"component", "Mass"},
                                      {"parameter", "m"}, {"value", 250}});
    expectReplyShape("parameter.set", good);
    EXPECT_EQ(good.data["parameter"]["value"], "250");
    const auto expression = session.handle({{"id", 2}, {"type", "parameter.set"}, {"component", "Mass"},
                                            {"parameter", "m"}, {"value", "2*125.5"}});
    EXPECT_TRUE(expression.ok) << expression.message;

    const auto bad = session.handle({{"id", 3}, {"type", "parameter.set"}, {"component", "Mass"},
                                     {"parameter", "m"}, {"value", "heavy*2"}});
    EXPECT_FALSE(bad.ok);
    EXPECT_EQ(bad.code, "invalid_parameter");
    EXPECT_NE(bad.message.find("heavy"), std::string::npos) << bad.message;
    const auto syntax = session.handle({{"id", 4}, {"type", "parameter.set"}, {"component", "Mass"},
                                        {"parameter", "m"}, {"value", "2*(3"}});
    EXPECT_EQ(syntax.code, "invalid_parameter");
    // Issue 38: "1e400" reads as infinity; refused naming the parameter, the old value kept.
    const auto infinite = session.handle({{"id", 7}, {"type", "parameter.set"}, {"component", "Mass"},
                                          {"parameter", "m"}, {"value", "1e400"}});
    EXPECT_EQ(infinite.code, "invalid_parameter");
    EXPECT_NE(infinite.message.find("Mass.m: '1e400' is not a finite number"), std::string::npos) << infinite.message;
    const auto notANumber = session.handle({{"id", 8}, {"type", "sysparam.set"}, {"name", "heavy"}, {"value", "nan"}});
    EXPECT_EQ(notANumber.code, "invalid_parameter");
    EXPECT_NE(notANumber.message.find("heavy: 'nan' is not a finite number"), std::string::npos) << notANumber.message;
    EXPECT_EQ(findByName(rootSystem(session).at("parameters"), "heavy"), nullptr) << "a new one that is refused is not added";

    const auto get = session.handle({{"id", 5}, {"type", "parameter.get"}, {"component", "Mass"}, {"parameter", "m"}});
    expectReplyShape("parameter.get", get);
    EXPECT_EQ(get.data["parameter"]["value"], "2*125.5");
    EXPECT_EQ(session.handle({{"id", 6}, {"type", "parameter.get"}, {"component", "Mass"}, {"parameter", "mass"}}).code,
              "not_found");
}

TEST(EditSession, SystemParametersCanBeSetAndUsed)
{
    EditSession session = openServo();
    const auto r = session.handle({{"id", 1}, {"type", "sysparam.set"}, {"name", "heavy"}, {"value", 300},
                                   {"unit", "kg"}, {"description", "a heavy mass"}});
    expectReplyShape("sysparam.set", r);
    EXPECT_EQ(r.data["parameter"], json({{"name", "heavy"}, {"value", "300"}, {"type", "double"},
                                         {"unit", "kg"}, {"description", "a heavy mass"}}));
    const auto use = session.handle({{"id", 2}, {"type", "parameter.set"}, {"component", "Mass"},
                                     {"parameter", "m"}, {"value", "heavy*2"}});
    EXPECT_TRUE(use.ok) << use.message;

    // A change keeps unit and description; a value that does not evaluate keeps the old one.
    const auto changed = session.handle({{"id", 3}, {"type", "sysparam.set"}, {"name", "heavy"}, {"value", "400"}});
    EXPECT_EQ(changed.data["parameter"]["unit"], "kg");
    const auto bad = session.handle({{"id", 4}, {"type", "sysparam.set"}, {"name", "heavy"}, {"value", "nothing+1"}});
    EXPECT_EQ(bad.code, "invalid_parameter");
    const json system = rootSystem(session);
    const json* p = findByName(system.at("parameters"), "heavy");
    ASSERT_NE(p, nullptr);
    EXPECT_EQ(p->at("value"), "400");
    const auto newBad = session.handle({{"id", 5}, {"type", "sysparam.set"}, {"name", "fresh"}, {"value", "nothing+1"}});
    EXPECT_EQ(newBad.code, "invalid_parameter");
    EXPECT_EQ(findByName(rootSystem(session).at("parameters"), "fresh"), nullptr);
}

TEST(EditSession, SystemParametersCanBeRemoved)
{
    EditSession session = openServo();
    ASSERT_TRUE(session.handle({{"id", 1}, {"type", "sysparam.set"}, {"name", "gone"}, {"value", 3}}).ok);
    const auto r = session.handle({{"id", 2}, {"type", "sysparam.remove"}, {"name", "gone"}});
    expectReplyShape("sysparam.remove", r);
    EXPECT_EQ(findByName(rootSystem(session).at("parameters"), "gone"), nullptr);
    EXPECT_EQ(session.handle({{"id", 3}, {"type", "sysparam.remove"}, {"name", "gone"}}).code, "not_found");
}

TEST(EditSession, ModelSettingsAreSavedWithTheModel)
{
    EditSession session = openServo();
    const auto r = session.handle({{"id", 1}, {"type", "model.settings"}, {"stop", 5}, {"log_samples", 1000}});
    expectReplyShape("model.settings", r);
    EXPECT_EQ(r.data["simulation"]["stop"], 5.0);
    EXPECT_EQ(r.data["simulation"]["log_samples"], 1000);
    EXPECT_EQ(r.data["simulation"]["step"], 1e-4);   // kept from the file
    EXPECT_EQ(session.handle({{"id", 2}, {"type", "model.settings"}, {"step", 0.1}, {"start", 9}, {"stop", 1}}).code,
              "bad_request");
    EditSession reloaded;
    std::string error;
    ASSERT_TRUE(reloaded.openHmf(session.saveHmf(), "again", error)) << error;
    const json simulation = rootSystem(reloaded).at("simulation");
    EXPECT_EQ(simulation["stop"], 5.0);
    EXPECT_EQ(simulation["log_samples"], 1000);
}

TEST(EditSession, LiveControlsAreReplacedWholeAndSavedInTheModelsGuiData)
{
    EditSession session = openServo();
    EXPECT_FALSE(rootSystem(session).contains("live_controls")) << "none until one is placed";
    const json controls = json::array({
        {{"kind", "slider"}, {"name", "Step.y_A"}, {"min", 0}, {"max", 1}, {"x", 120.5}, {"y", 40}},
        {{"kind", "switch"}, {"name", "Sub$Switch.state"}, {"min", 0}, {"max", 1}, {"off", 0}, {"on", 2},
         {"x", -5}, {"y", 7}, {"system", {"Sub"}}},
    });
    const auto r = session.handle({{"id", 1}, {"type", "model.controls"}, {"controls", controls}});
    expectReplyShape("model.controls", r);
    EXPECT_EQ(r.data["controls"], controls);
    EXPECT_EQ(rootSystem(session).at("live_controls"), controls);
    // in the root's GUI data, not among its parameters
    const std::string hmf = session.saveHmf();
    EXPECT_NE(hmf.find("<tlmhub_livecontrols>"), std::string::npos);
    EXPECT_EQ(findByName(rootSystem(session).at("parameters"), "tlmhub_live_controls"), nullptr);
    EditSession reloaded;
    std::string error;
    ASSERT_TRUE(reloaded.openHmf(hmf, "again", error)) << error;
    EXPECT_EQ(rootSystem(reloaded).at("live_controls"), controls);

    EXPECT_EQ(session.handle({{"id", 2}, {"type", "model.controls"},
                              {"controls", {{{"kind", "dial"}, {"name", "A.b"}, {"min", 0}, {"max", 1}, {"x", 0}, {"y", 0}}}}})
                  .code,
              "bad_request");
    EXPECT_EQ(rootSystem(session).at("live_controls"), controls) << "a refused request changes nothing";
    ASSERT_TRUE(session.handle({{"id", 3}, {"type", "model.controls"}, {"controls", json::array()}}).ok);
    EXPECT_FALSE(rootSystem(session).contains("live_controls"));
    EXPECT_EQ(session.saveHmf().find("tlmhub_livecontrols"), std::string::npos);
}

TEST(EditSession, MoveChangesOnlyThePose)
{
    EditSession session = openServo();
    const json pose = {{"x", 1.25}, {"y", 2}, {"angle", 270}, {"flipped", true}};
    const auto r = session.handle({{"id", 1}, {"type", "component.move"}, {"name", "Mass"}, {"pose", pose}});
    expectReplyShape("component.move", r);
    const json system = rootSystem(session);
    const json* mass = findByName(system.at("components"), "Mass");
    EXPECT_EQ(mass->at("pose"), json({{"x", 1.25}, {"y", 2.0}, {"angle", 270.0}, {"flipped", true}}));
    // Other GUI data of the component stays (Hopsan needs it).
    EXPECT_NE(session.saveHmf().find("hopsanobjectappearance"), std::string::npos);
    EXPECT_EQ(session.handle({{"id", 2}, {"type", "component.move"}, {"name", "Nobody"}, {"pose", pose}}).code, "not_found");
}

TEST(EditSession, SaveAndReloadKeepsNewComponentPoseAndParameter)
{
    EditSession session = openServo();
    const auto added = session.handle({{"id", 1}, {"type", "component.add"}, {"component_type", "SignalGain"},
                                       {"name", "Extra gain"}, {"pose", {{"x", 111}, {"y", 222}, {"angle", 180}, {"flipped", false}}}});
    ASSERT_TRUE(added.ok) << added.message;
    const std::string name = added.data["component"]["name"].get<std::string>();
    EXPECT_EQ(name, "Extra_gain");
    ASSERT_TRUE(session.handle({{"id", 2}, {"type", "parameter.set"}, {"component", name}, {"parameter", "k#Value"},
                                {"value", 3.5}}).ok);
    ASSERT_TRUE(session.handle({{"id", 3}, {"type", "component.move"}, {"name", "Mass"},
                                {"pose", {{"x", 5}, {"y", 6}, {"angle", 0}, {"flipped", false}}}}).ok);

    const std::string hmf = session.saveHmf();
    EXPECT_NE(hmf.find("<pose x=\"111\" y=\"222\" a=\"180\" flipped=\"false\""), std::string::npos);
    EditSession reloaded;
    std::string error;
    ASSERT_TRUE(reloaded.openHmf(hmf, "Position Servo", error)) << error;
    const json system = rootSystem(reloaded);
    const json* gain = findByName(system.at("components"), name);
    ASSERT_NE(gain, nullptr);
    EXPECT_EQ(gain->at("type"), "SignalGain");
    EXPECT_EQ(gain->at("pose"), json({{"x", 111.0}, {"y", 222.0}, {"angle", 180.0}, {"flipped", false}}));
    EXPECT_EQ(findByName(gain->at("parameters"), "k#Value")->at("value"), "3.5");
    EXPECT_EQ(findByName(system.at("components"), "Mass")->at("pose").at("x"), 5.0);
    EXPECT_EQ(system.at("connections").size(), 24u);
}

TEST(EditSession, SavingKeepsEveryConnectionLine)
{
    // Files list some connections in the other direction than the saver writes them.
    for (const char* file : {"Position Servo.hmf", "Sub System Example.hmf", "Load Sensing System.hmf"}) {
        EditSession session;
        std::string error;
        ASSERT_TRUE(session.openHmf(readFile(kModels + file), file, error)) << error;
        EditSession reloaded;
        ASSERT_TRUE(reloaded.openHmf(session.saveHmf(), file, error)) << error;
        const json before = json(session.model());
        const json after = json(reloaded.model());
        EXPECT_EQ(before, after) << file;
        std::size_t lines = 0;
        for (const json& c : before["system"]["connections"]) lines += c["points"].empty() ? 0 : 1;
        EXPECT_EQ(lines, before["system"]["connections"].size()) << file << ": every connection has a line";
    }
}

TEST(EditSession, SystemPathNavigatesIntoSubsystems)
{
    EditSession session;
    std::string error;
    ASSERT_TRUE(session.openHmf(readFile(kModels + "Sub System Example.hmf"), "Sub", error)) << error;
    const auto r = session.handle({{"id", 1}, {"type", "component.add"}, {"component_type", "SignalGain"},
                                   {"system", {"Servo1"}}});
    ASSERT_TRUE(r.ok) << r.message;
    const json root = rootSystem(session);
    const json* servo = findByName(root.at("components"), "Servo1");
    EXPECT_NE(findByName(servo->at("system").at("components"), r.data["component"]["name"].get<std::string>()), nullptr);
    EXPECT_EQ(findByName(root.at("components"), r.data["component"]["name"].get<std::string>()), nullptr);

    const auto p = session.handle({{"id", 2}, {"type", "parameter.get"}, {"component", "Cylinder_C"},
                                   {"parameter", "V_1#Value"}, {"system", {"Servo1"}}});
    EXPECT_TRUE(p.ok) << p.message;
    const auto missing = session.handle({{"id", 3}, {"type", "model.get"}});
    EXPECT_TRUE(missing.ok);
    const auto bad = session.handle({{"id", 4}, {"type", "component.remove"}, {"name", "Cylinder_C"},
                                     {"system", {"Servo1", "Nowhere"}}});
    EXPECT_EQ(bad.code, "not_found");
    EXPECT_NE(bad.message.find("Nowhere"), std::string::npos);

    // A new subsystem, then a component inside it.
    const auto sub = session.handle({{"id", 5}, {"type", "component.add"}, {"component_type", "Subsystem"}, {"name", "Inner"}});
    ASSERT_TRUE(sub.ok) << sub.message;
    EXPECT_EQ(sub.data["component"]["kind"], "system");
    EXPECT_TRUE(session.handle({{"id", 6}, {"type", "component.add"}, {"component_type", "SignalStep"},
                                {"system", {"Inner"}}}).ok);
}

TEST(EditSession, CreateEmptyThenBuildAModel)
{
    EditSession session;
    EXPECT_FALSE(session.isOpen());
    EXPECT_EQ(session.handle({{"id", 1}, {"type", "model.get"}}).code, "not_open");
    session.createEmpty("My model");
    ASSERT_TRUE(session.isOpen());
    const auto get = session.handle({{"id", 2}, {"type", "model.get"}});
    expectReplyShape("model.get", get);
    EXPECT_EQ(get.data["model"]["name"], "My model");
    EXPECT_EQ(get.data["model"]["system"]["name"], "My_model");
    EXPECT_TRUE(session.handle({{"id", 3}, {"type", "component.add"}, {"component_type", "SignalStep"}}).ok);
    EditSession reloaded;
    std::string error;
    ASSERT_TRUE(reloaded.openHmf(session.saveHmf(), "My model", error)) << error;
    EXPECT_EQ(rootSystem(reloaded).at("components").size(), 1u);
}

TEST(EditSession, NeverThrowsOnMalformedRequests)
{
    EditSession session = openServo();
    const json requests[] = {
        json::array(),
        json(5),
        json::object(),
        {{"type", 7}},
        {{"type", "simulate.start"}},
        {{"type", "component.add"}},
        {{"type", "component.add"}, {"component_type", 5}},
        {{"type", "component.add"}, {"component_type", "SignalGain"}, {"pose", {{"x", "a"}}}},
        {{"type", "component.add"}, {"component_type", "SignalGain"}, {"system", "Servo1"}},
        {{"type", "component.add"}, {"component_type", "SignalGain"}, {"system", {1}}},
        {{"type", "component.move"}, {"name", "Mass"}},
        {{"type", "connect"}, {"from", "Mass.P1"}, {"to", json::object()}},
        {{"type", "connect"}, {"from", {{"component", "Step"}, {"port", "out"}}},
         {"to", {{"component", "Sink"}, {"port", "in"}}}, {"points", {{1}}}},
        {{"type", "parameter.set"}, {"component", "Mass"}, {"parameter", "m"}, {"value", true}},
        {{"type", "parameter.set"}, {"component", "Mass"}, {"parameter", "m"}, {"value", nullptr}},
        {{"type", "sysparam.set"}, {"name", "x"}, {"value", 1}, {"param_type", "colour"}},
        {{"type", "sysparam.set"}, {"name", "bad name"}, {"value", 1}},
        {{"type", "component.rename"}, {"name", "Mass"}},
    };
    for (const json& request : requests) {
        EditSession::Result r;
        EXPECT_NO_THROW(r = session.handle(request)) << request.dump();
        EXPECT_FALSE(r.ok) << request.dump();
        EXPECT_FALSE(r.code.empty()) << request.dump();
    }
    EXPECT_EQ(session.handle(json::array()).code, "bad_request");
    EXPECT_EQ(session.handle({{"type", "simulate.start"}}).code, "unknown_message_type");
    EXPECT_EQ(session.handle({{"type", "component.add"}, {"component_type", 5}}).code, "bad_request");
    EXPECT_EQ(session.handle({{"type", "sysparam.set"}, {"name", "x"}, {"value", 1}, {"param_type", "colour"}}).code,
              "invalid_parameter");
    // The model is intact after all that.
    EXPECT_EQ(rootSystem(session).at("components").size(), 20u);
}

TEST(EditSession, OpenRefusesTextThatIsNotAModel)
{
    EditSession session;
    std::string error;
    EXPECT_FALSE(session.openHmf("<notamodel/>", "x", error));
    EXPECT_FALSE(error.empty());
    EXPECT_FALSE(session.openHmf("not xml at all", "x", error));
    EXPECT_FALSE(session.isOpen());
}

TEST(EditSession, GroupAndItsUndoUngroupGiveTheModelBack)
{
    EditSession session = openServo();
    const std::string original = session.saveHmf();
    const json names = {"Pressure_Relief_Valve", "Step", "Q_type_Fixed_Displacement_Pump_1"};
    const auto grouped = session.handle({{"id", 1}, {"type", "model.group"}, {"names", names}, {"name", "Pump side"}});
    expectReplyShape("model.group", grouped);
    const std::string sub = grouped.data.at("name").get<std::string>();
    EXPECT_EQ(sub, "Pump_side");
    const json system = rootSystem(session);
    const json* subsystem = findByName(system.at("components"), sub);
    ASSERT_NE(subsystem, nullptr);
    EXPECT_EQ(subsystem->at("kind"), "system");
    EXPECT_EQ(session.openModel()->root().component(sub)->kind(), tlmhub::CqsKind::Q);
    EXPECT_EQ(findByName(system.at("components"), "Step"), nullptr);
    // Placed among the components it replaces.
    EXPECT_GT(subsystem->at("pose").at("x").get<double>(), 0.0);

    // The client's undo of model.group is model.ungroup of the reply's name.
    const auto ungrouped = session.handle({{"id", 2}, {"type", "model.ungroup"}, {"name", sub}});
    expectReplyShape("model.ungroup", ungrouped);
    EXPECT_EQ(ungrouped.data.at("names"), names);
    EXPECT_EQ(session.saveHmf(), original);
    // Redo groups again.
    const auto regrouped = session.handle({{"id", 3}, {"type", "model.group"}, {"names", names}, {"name", sub}});
    expectReplyShape("model.group", regrouped);
    EXPECT_EQ(regrouped.data.at("name"), sub);
}

TEST(EditSession, GroupWithAnUndefinedKindIsRefusedWithTheReason)
{
    EditSession session = openServo();
    const std::string original = session.saveHmf();
    const auto r = session.handle({{"id", 1}, {"type", "model.group"}, {"names", {"Mass", "Cylinder_C"}}, {"name", "Sub"}});
    EXPECT_FALSE(r.ok);
    EXPECT_EQ(r.code, "illegal_grouping");
    EXPECT_NE(r.message.find("undefined C/Q/S kind"), std::string::npos) << r.message;
    EXPECT_EQ(session.saveHmf(), original);

    const auto missing = session.handle({{"id", 2}, {"type", "model.group"}, {"names", {"Nobody"}}, {"name", "Sub"}});
    EXPECT_EQ(missing.code, "not_found");
    const auto notASubsystem = session.handle({{"id", 3}, {"type", "model.ungroup"}, {"name", "Mass"}});
    EXPECT_EQ(notASubsystem.code, "not_found");
    EXPECT_EQ(session.saveHmf(), original);
}
