// The GUI layout as typed values of the Model: read from the model file, and written back
// on save with only the changed values rewritten, the rest of the file as it was.
#include "TestHelpers.h"

#include "core/Model.h"
#include "core/hmf/HmfLoader.h"
#include "core/hmf/GuiLayoutXml.h"
#include "core/hmf/HmfSaver.h"

#include <pugixml.hpp>

#include <filesystem>
#include <sstream>

using namespace tlmhub;
using namespace tlmhub::test;

namespace {

Model loadSubSystemExample()
{
    LoadedModel loaded = loadHmfFile(sharedDir() + "/hopsan-models/Example Models/Sub System Example.hmf");
    EXPECT_FALSE(loaded.hasErrors()) << loaded.firstError();
    return Model(std::move(loaded.root));
}

// The lines of `after` that differ from the same line of `before`, without indentation;
// the texts must have as many lines.
std::vector<std::string> linesChangedBySave(const std::string& before, const std::string& after)
{
    std::istringstream a(before), b(after);
    std::vector<std::string> changed;
    std::string lineA, lineB;
    while (true) {
        const bool moreA = static_cast<bool>(std::getline(a, lineA));
        const bool moreB = static_cast<bool>(std::getline(b, lineB));
        if (moreA != moreB) {
            changed.push_back("<the texts differ in length>");
            return changed;
        }
        if (!moreA) return changed;
        if (lineA != lineB) changed.push_back(lineB.substr(lineB.find_first_not_of(' ')));
    }
}

// Every component's, system port's and connection's layout, with its path, in model order.
void collectLayouts(const System& s, const std::string& path, std::vector<std::string>& out)
{
    auto pose = [](std::ostream& os, const Pose& p) {
        os << p.x << ',' << p.y << ',' << p.angle << (p.flipped ? ",flipped" : "");
    };
    for (const Component* c : s.componentsInOrder()) {
        std::ostringstream os;
        os.precision(17);
        os << path << c->name() << ": ";
        pose(os, c->layout.pose);
        if (const auto& n = c->layout.nameText) os << " name " << n->position << (n->visible ? " visible" : "");
        for (const IconPort& p : c->layout.iconPorts)
            os << ' ' << p.name << '@' << p.x << ',' << p.y << ',' << p.angle << (p.autoplaced ? "" : ",fixed")
               << (p.enabled ? "" : ",disabled");
        out.push_back(os.str());
        if (c->isSystem()) collectLayouts(static_cast<const System&>(*c), path + c->name() + "$", out);
    }
    for (const auto& [name, extras] : s.systemPortExtras) {
        std::ostringstream os;
        os.precision(17);
        os << path << name << ": ";
        pose(os, extras.layout.pose);
        out.push_back(os.str());
    }
    for (const auto& [key, extras] : s.connectionExtras) {
        std::ostringstream os;
        os.precision(17);
        os << path << key << ':';
        for (const LinePoint& p : extras.layout.points) os << ' ' << p[0] << ',' << p[1];
        out.push_back(os.str());
    }
}

// The layout an element's preserved XML says: what the saver compares the typed values with.
pugi::xml_node parsedExtras(pugi::xml_document& doc, const std::string& preservedXml)
{
    const std::string element = "<element>" + preservedXml + "</element>";
    EXPECT_TRUE(doc.load_string(element.c_str()));
    return doc.first_child();
}

// Every typed layout of `s` and its subsystems is what the XML kept beside it says, so saving
// rewrites none of it.
void expectLayoutsAsTheirXmlSays(const System& s, const std::string& model)
{
    pugi::xml_document doc;
    for (const Component* c : s.componentsInOrder()) {
        EXPECT_EQ(c->layout, guixml::readObjectLayout(parsedExtras(doc, c->preservedXml))) << model << ": " << c->name();
        if (c->isSystem()) expectLayoutsAsTheirXmlSays(static_cast<const System&>(*c), model);
    }
    for (const auto& [name, extras] : s.systemPortExtras)
        EXPECT_EQ(extras.layout, guixml::readObjectLayout(parsedExtras(doc, extras.preservedXml))) << model << ": " << name;
    for (const auto& [key, extras] : s.connectionExtras)
        EXPECT_EQ(extras.layout, guixml::readConnectionLayout(parsedExtras(doc, extras.preservedXml))) << model << ": " << key;
}

} // namespace

TEST(GuiLayout, LoadingGivesThePosesNameTextsIconPortsAndLinesOfTheFile)
{
    const Model model = loadSubSystemExample();
    const Component* force = model.root().component("ForceSource1");
    ASSERT_NE(force, nullptr);
    EXPECT_EQ(force->layout.pose, (Pose{.x = 2564.233966, .y = 2406.27416, .angle = 0, .flipped = true}));
    EXPECT_EQ(force->layout.nameText, (NameText{.position = 0, .visible = false}));
    EXPECT_TRUE(force->layout.iconPorts.empty());

    const System* servo = model.root().subsystem("Servo1");
    ASSERT_NE(servo, nullptr);
    EXPECT_EQ(servo->layout.pose, (Pose{.x = 2425.728297, .y = 2406.27416}));
    ASSERT_EQ(servo->layout.iconPorts.size(), 4u);
    EXPECT_EQ(servo->layout.iconPorts[1], (IconPort{.name = "Container_Port_2", .x = 0.6666666667, .y = 1, .angle = 90}));
    EXPECT_EQ(servo->systemPortExtras.at("Container_Port_1").layout.pose, (Pose{.x = 2320, .y = 2498}));

    const ConnectionLayout& line = servo->connectionExtras.at("Translational_Mass.P1|Cylinder_C.P3").layout;
    ASSERT_EQ(line.points.size(), 4u);
    EXPECT_EQ(line.points.front(), (LinePoint{2462.30000000000018189894, 2333.80000000000018189894}));
    EXPECT_EQ(line.points.back(), (LinePoint{2442.30000000000018189894, 2333.80000000000018189894}));
}

TEST(GuiLayout, ASetPoseRewritesOnlyItsChangedAttributes)
{
    Model model = loadSubSystemExample();
    const std::string before = model.toHmf();
    Pose& pose = model.root().component("ForceSource1")->layout.pose;
    pose.x = 100;
    pose.angle = 90;
    const std::string after = model.toHmf();
    // y and flipped keep their text and place; every other line of the file is as it was.
    EXPECT_EQ(linesChangedBySave(before, after),
              std::vector<std::string>{R"(<pose y="2406.27416" x="100" flipped="true" a="90" />)"});

    const LoadedModel reloaded = loadHmfString(after, ".", "saved");
    ASSERT_FALSE(reloaded.hasErrors()) << reloaded.firstError();
    EXPECT_EQ(reloaded.root->component("ForceSource1")->layout.pose,
              (Pose{.x = 100, .y = 2406.27416, .angle = 90, .flipped = true}));
}

TEST(GuiLayout, NameTextsIconPortsAndSystemPortPosesRewriteOnlyTheirOwnLines)
{
    Model model = loadSubSystemExample();
    const std::string before = model.toHmf();
    System& servo = *model.root().subsystem("Servo1");
    servo.layout.nameText->visible = true;
    servo.layout.iconPorts[0].x = 0.5;
    servo.systemPortExtras.at("Container_Port_3").layout.pose.y = 2400;
    EXPECT_EQ(linesChangedBySave(before, model.toHmf()),
              (std::vector<std::string>{
                  R"(<nametext visible="1" position="0" />)",
                  R"(<port autoplaced="true" y="0.5" name="Container_Port_3" x="0.5" enabled="true" a="0" />)",
                  R"(<pose y="2400" x="2597" flipped="false" a="0" />)"}));
}

TEST(GuiLayout, LinePointsAreSavedWithTheirGeometriesBesideTheOtherLineData)
{
    Model model = loadSubSystemExample();
    System& servo = *model.root().subsystem("Servo1");
    servo.connectionExtras.at("Translational_Mass.P1|Cylinder_C.P3").layout.points = {{0, 0}, {10, 0}, {10, 5}, {20, 15}};
    const std::string saved = model.toHmf();

    pugi::xml_document doc;
    ASSERT_TRUE(doc.load_string(saved.c_str()));
    const pugi::xml_node connect = doc.select_node(
        "//system[@name='Servo1']/connections/connect[@startcomponent='Translational_Mass']").node();
    ASSERT_TRUE(connect);
    std::vector<std::string> children, geometries;
    for (pugi::xml_node child : connect.child("hopsangui").children()) children.push_back(child.name());
    for (pugi::xml_node g : connect.child("hopsangui").child("geometries").children("geometry"))
        geometries.push_back(g.text().get());
    // The style Hopsan keeps for the line is still there, after the new points.
    EXPECT_EQ(children, (std::vector<std::string>{"coordinates", "geometries", "style"}));
    // A horizontal segment is dragged vertically and the other way round.
    EXPECT_EQ(geometries, (std::vector<std::string>{"vertical", "horizontal", "diagonal"}));

    const LoadedModel reloaded = loadHmfString(saved, ".", "saved");
    ASSERT_FALSE(reloaded.hasErrors()) << reloaded.firstError();
    EXPECT_EQ(reloaded.root->subsystem("Servo1")->connectionExtras.at("Translational_Mass.P1|Cylinder_C.P3").layout.points,
              (std::vector<LinePoint>{{0, 0}, {10, 0}, {10, 5}, {20, 15}}));
}

TEST(GuiLayout, ANewComponentSavesAPoseOnlyAwayFromTheOrigin)
{
    Model model;
    add(model.root(), "MechanicTranslationalMass", "Placed");
    add(model.root(), "MechanicTranslationalMass", "AtOrigin");
    model.root().component("Placed")->layout.pose = {.x = 10, .y = -20, .angle = 180};
    pugi::xml_document doc;
    ASSERT_TRUE(doc.load_string(model.toHmf().c_str()));
    const pugi::xml_node objects = doc.child("hopsanmodelfile").child("system").child("objects");
    std::ostringstream pose;
    objects.find_child_by_attribute("component", "name", "Placed").child("hopsangui").first_child().print(
        pose, "", pugi::format_raw);
    EXPECT_EQ(pose.str(), R"(<pose x="10" y="-20" a="180" flipped="false"/>)");
    // A file without a pose places the component at the origin, for Hopsan as for us.
    EXPECT_FALSE(objects.find_child_by_attribute("component", "name", "AtOrigin").child("hopsangui"));
}

// An unchanged model saves as the preserved XML alone did before the layout was typed.
TEST(GuiLayout, EverySharedModelSavesWithNoLayoutRewrittenAndReloadsWithTheSameLayout)
{
    std::size_t models = 0;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(sharedDir() + "/hopsan-models")) {
        if (entry.path().extension() != ".hmf") continue;
        LoadedModel first = loadHmfFile(entry.path().string());
        if (!first.root) continue;
        ++models;
        pugi::xml_document rootExtras;
        EXPECT_EQ(first.root->layout, guixml::readObjectLayout(parsedExtras(rootExtras, first.root->preservedXml)));
        expectLayoutsAsTheirXmlSays(*first.root, entry.path().string());
        const std::string saved = saveHmfString(*first.root);
        const LoadedModel second = loadHmfString(saved, first.root->modelDirectory, "saved");
        ASSERT_TRUE(second.root) << entry.path();
        std::vector<std::string> a, b;
        collectLayouts(*first.root, "", a);
        collectLayouts(*second.root, "", b);
        EXPECT_EQ(a, b) << entry.path();
        EXPECT_EQ(saveHmfString(*second.root), saved) << entry.path();
    }
    EXPECT_GT(models, 100u);
}

TEST(GuiLayout, LiveControlsAreSavedInTheRootsGuiDataAndReloadTheSame)
{
    Model model = loadSubSystemExample();
    const std::string before = model.toHmf();
    const std::vector<LiveControlLayout> controls = {
        {.kind = "slider", .name = "ForceSource1.f", .min = -100, .max = 250.5, .off = std::nullopt,
         .on = std::nullopt, .x = 2410, .y = 2380, .system = {}},
        {.kind = "switch", .name = "Servo1$Gain.k", .min = 0, .max = 1, .off = 0.5, .on = 2, .x = -3.25, .y = 7,
         .system = {"Servo1"}},
    };
    model.root().liveControls = controls;
    const std::string saved = model.toHmf();
    EXPECT_NE(saved.find("<tlmhub_livecontrols>"), std::string::npos);

    LoadedModel reloaded = loadHmfString(saved, ".", "saved");
    ASSERT_FALSE(reloaded.hasErrors()) << reloaded.firstError();
    EXPECT_EQ(reloaded.root->liveControls, controls);
    // inside the root's <hopsangui>, where Hopsan keeps the GUI's own data of the model
    pugi::xml_document doc;
    ASSERT_TRUE(doc.load_string(saved.c_str()));
    EXPECT_EQ(doc.select_nodes("/hopsanmodelfile/system/hopsangui/tlmhub_livecontrols/control").size(), 2u);

    // Saved again unchanged, the file is the same; with none left, as it was before.
    Model again(std::move(reloaded.root));
    EXPECT_EQ(again.toHmf(), saved);
    again.root().liveControls.clear();
    EXPECT_EQ(again.toHmf(), before);
}
