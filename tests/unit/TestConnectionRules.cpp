// Connection rules of core.md §2.5: every refusal names both ports and a reason.
#include "TestHelpers.h"

using namespace tlmhub;
using namespace tlmhub::test;

namespace {

std::string refuse(System& s, const std::string& a, const std::string& pa, const std::string& b,
                   const std::string& pb)
{
    const Status refused = s.connect(a, pa, b, pb);
    EXPECT_FALSE(refused);
    return refused.message();
}

} // namespace

TEST(ConnectionRules, CToQHydraulicIsAccepted)
{
    System s;
    add(s, "HydraulicVolume", "V");
    add(s, "HydraulicLaminarOrifice", "O");
    connectOk(s, "V", "P1", "O", "P1");
    EXPECT_EQ(s.component("V")->port("P1")->node(), s.component("O")->port("P1")->node());
}

TEST(ConnectionRules, WrongNodeTypeIsRefused)
{
    System s;
    add(s, "HydraulicVolume", "V");
    add(s, "MechanicTranslationalMass", "M");
    const std::string err = refuse(s, "V", "P1", "M", "P1");
    EXPECT_NE(err.find("V.P1"), std::string::npos);
    EXPECT_NE(err.find("M.P1"), std::string::npos);
    EXPECT_NE(err.find("node types differ"), std::string::npos) << err;
}

TEST(ConnectionRules, TwoCComponentsAreRefused)
{
    System s;
    add(s, "HydraulicVolume", "V1");
    add(s, "HydraulicVolume", "V2");
    const std::string err = refuse(s, "V1", "P1", "V2", "P1");
    EXPECT_NE(err.find("two C-type"), std::string::npos) << err;
}

TEST(ConnectionRules, TwoQComponentsAreRefused)
{
    System s;
    add(s, "HydraulicLaminarOrifice", "O1");
    add(s, "HydraulicLaminarOrifice", "O2");
    const std::string err = refuse(s, "O1", "P2", "O2", "P1");
    EXPECT_NE(err.find("two Q-type"), std::string::npos) << err;
}

TEST(ConnectionRules, TwoWritePortsOnOneSignalNodeAreRefused)
{
    System s;
    add(s, "SignalConstant", "A");
    add(s, "SignalConstant", "B");
    add(s, "SignalGain", "G");
    connectOk(s, "A", "y", "G", "in");
    const std::string err = refuse(s, "B", "y", "G", "in");
    EXPECT_NE(err.find("only one write port"), std::string::npos) << err;
}

TEST(ConnectionRules, WritePortOnPowerNodeIsRefused)
{
    System s;
    add(s, "HydraulicVolume", "V");
    add(s, "HydraulicLaminarOrifice", "O");
    add(s, "HydraulicPressureSensor", "S");
    connectOk(s, "V", "P1", "O", "P1");
    connectOk(s, "S", "P1", "V", "P1");   // a sensor may read a power node
    const Status refused = s.connect("S", "out", "V", "P2");
    EXPECT_EQ(refused.code(), StatusCode::IllegalConnection);
    EXPECT_FALSE(refused.message().empty());
}

TEST(ConnectionRules, ReadPortToMultiportIsRefused)
{
    System s;
    add(s, "SignalGain", "G");
    add(s, "SignalSink", "Sink");
    const std::string err = refuse(s, "G", "in", "Sink", "in");
    EXPECT_NE(err.find("read port cannot be connected to a multiport"), std::string::npos) << err;
}

TEST(ConnectionRules, UnknownComponentOrPortIsNamed)
{
    System s;
    add(s, "HydraulicVolume", "V");
    std::string err = refuse(s, "V", "P9", "Nope", "P1");
    EXPECT_NE(err.find("P9"), std::string::npos) << err;
    err = refuse(s, "V", "P1", "Nope", "P1");
    EXPECT_NE(err.find("Nope"), std::string::npos) << err;
    EXPECT_EQ(s.connect("V", "P1", "Nope", "P1").code(), StatusCode::NotFound);
}

TEST(ConnectionRules, SystemPortIsNamedByItsNameTwice)
{
    // As the loader reads and the saver writes it: component and port are both the system
    // port's name. Any other port name names no port.
    System s;
    add(s, "SignalGain", "G");
    s.addSystemPort("in");
    const Status misnamed = s.connect("in", "y", "G", "in");
    EXPECT_EQ(misnamed.code(), StatusCode::NotFound);
    EXPECT_NE(misnamed.message().find("in.y"), std::string::npos) << misnamed.message();
    EXPECT_FALSE(s.systemPort("in")->isConnected());

    connectOk(s, "in", "in", "G", "in");
    EXPECT_EQ(s.disconnect("in", "y", "G", "in").code(), StatusCode::NotFound);
    EXPECT_TRUE(s.systemPort("in")->isConnected());
}

TEST(ConnectionRules, DisconnectOfPortsNotConnectedIsIllegal)
{
    System s;
    add(s, "HydraulicVolume", "V");
    add(s, "HydraulicLaminarOrifice", "O");
    const Status refused = s.disconnect("V", "P1", "O", "P1");
    EXPECT_EQ(refused.code(), StatusCode::IllegalConnection);
    EXPECT_NE(refused.message().find("V.P1"), std::string::npos) << refused.message();
    EXPECT_NE(refused.message().find("O.P1"), std::string::npos) << refused.message();
    EXPECT_EQ(s.disconnect("V", "P9", "O", "P1").code(), StatusCode::NotFound);
}

TEST(ConnectionRules, ReadPortToNothingFailsTheModelCheck)
{
    // A required read port left unconnected is reported by the model check.
    System s;
    add(s, "HydraulicVolume", "V");
    add(s, "HydraulicLaminarOrifice", "O");
    connectOk(s, "V", "P1", "O", "P1");
    const Status checked = s.check();
    EXPECT_EQ(checked.code(), StatusCode::UnconnectedPort);
    EXPECT_NE(checked.message().find("not connected"), std::string::npos) << checked.message();
}

TEST(ConnectionRules, DisconnectSplitsTheNode)
{
    System s;
    add(s, "HydraulicVolume", "V");
    add(s, "HydraulicLaminarOrifice", "O");
    connectOk(s, "V", "P1", "O", "P1");
    ASSERT_TRUE(isOk(s.disconnect("V", "P1", "O", "P1")));
    EXPECT_NE(s.component("V")->port("P1")->node(), s.component("O")->port("P1")->node());
    EXPECT_EQ(s.disconnect("V", "P1", "O", "P1").code(), StatusCode::IllegalConnection);
}

TEST(ConnectionRules, MultiportTakesManyConnectionsWithOneNodeEach)
{
    System s;
    add(s, "HydraulicVolumeMultiPort", "V");
    add(s, "HydraulicLaminarOrifice", "O1");
    add(s, "HydraulicLaminarOrifice", "O2");
    connectOk(s, "V", "P1", "O1", "P1");
    connectOk(s, "V", "P1", "O2", "P1");
    Port* mp = s.component("V")->port("P1");
    ASSERT_EQ(mp->subPorts.size(), 2u);
    EXPECT_NE(mp->subPorts[0]->node(), mp->subPorts[1]->node());
}

TEST(ConnectionRules, NamesStayUniqueOnAddAndRename)
{
    System s;
    EXPECT_EQ(add(s, "HydraulicVolume", "Vol"), "Vol");
    EXPECT_EQ(add(s, "HydraulicVolume", "Vol"), "Vol_1");
    EXPECT_EQ(add(s, "HydraulicVolume", "Vol"), "Vol_2");
    // Renaming to a taken name: Vol -> Vol_1 (taken) -> Vol_2 (freed by this rename).
    EXPECT_EQ(*s.renameComponent("Vol_2", "Vol"), "Vol_2");
    EXPECT_EQ(*s.renameComponent("Vol_2", "2/2 Valve"), "2_2_Valve");
    EXPECT_EQ(*s.renameComponent("Vol_1", "Valve_3"), "Valve_3");
    EXPECT_EQ(s.renameComponent("Nope", "Other").status().code(), StatusCode::NotFound);
    EXPECT_EQ(add(s, "HydraulicVolume", "Valve_3"), "Valve_1");
    EXPECT_EQ(add(s, "HydraulicVolume", "time"), "time_1");   // reserved name
}

TEST(ConnectionRules, RemoveComponentDisconnectsFirst)
{
    System s;
    add(s, "HydraulicVolume", "V");
    add(s, "HydraulicLaminarOrifice", "O");
    connectOk(s, "V", "P1", "O", "P1");
    ASSERT_TRUE(isOk(s.removeComponent("O")));
    EXPECT_FALSE(s.component("V")->port("P1")->isConnected());
    EXPECT_EQ(s.removeComponent("O").code(), StatusCode::NotFound);
}
