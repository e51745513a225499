// The hand-written integrator FMU (y' = k u) imported through FMIWrapper into a model file,
// run by the core and by tlmhub-cli, against its exact discrete solution.
#include "FmuImportTestSupport.h"

#include "core/ComponentFactory.h"
#include "core/Model.h"
#include "core/ParameterPath.h"
#include "core/Simulation.h"
#include "core/hmf/HmfLoader.h"
#include "fmu/FmuLoadPolicy.h"

#include <cmath>

namespace tlmhub::fmu::test {
namespace {

constexpr double k = 3.0, y0 = 0.5, amplitude = 2.0, tStep = 0.1, h = 0.001;

class FmuImport : public ::testing::Test {
protected:
    void SetUp() override
    {
        setFmuLoadPolicy(FmuLoadPolicy::anywhere());
        writeIntegratorFmu(dir.path() / "integrator.fmu");
        fs::copy_file(sourceDir() / "tests/fmu/models/integrator.hmf", modelFile());
    }
    void TearDown() override { setFmuLoadPolicy(FmuLoadPolicy::nowhere()); }
    fs::path modelFile() const { return dir.path() / "integrator.hmf"; }

    TemporaryDirectory dir;
};

// The FMU integrates the input held over each step exactly: y_n = y_{n-1} + k u_n h, with
// u_n the step's output at the end of the step (the wrapper runs after the step source).
void expectExactSolution(const std::vector<double>& time, const std::vector<double>& u, const std::vector<double>& y)
{
    ASSERT_EQ(time.size(), 1001u);
    ASSERT_EQ(u.size(), time.size());
    ASSERT_EQ(y.size(), time.size());
    EXPECT_DOUBLE_EQ(y[0], y0);
    double expected = y0;
    for (std::size_t n = 1; n < time.size(); ++n) {
        expected += k * u[n] * h;
        ASSERT_NEAR(y[n], expected, 1e-12) << "t = " << time[n];
    }
    // And the continuous solution y0 + k A (t - t_step) to within one step of the input.
    EXPECT_NEAR(y.back(), y0 + k * amplitude * (1.0 - tStep), k * amplitude * h * 1.0001);
    EXPECT_GT(y.back(), 5.0);   // the input really came through: 0.5 + 3 * 2 * 0.9 = 5.9
}

TEST_F(FmuImport, ModelFileConnectsToTheFmusPortsAndSetsItsParameters)
{
    LoadedModel loaded = loadHmfFile(modelFile().string());
    ASSERT_FALSE(loaded.hasErrors()) << loaded.firstError();
    Component* wrapper = loaded.root->component("Integrator");
    ASSERT_TRUE(wrapper);
    EXPECT_EQ(wrapper->kind(), CqsKind::S);
    ASSERT_TRUE(wrapper->port("u"));
    ASSERT_TRUE(wrapper->port("y"));
    EXPECT_TRUE(wrapper->port("u")->isConnected());
    EXPECT_TRUE(wrapper->port("y")->isConnected());
    ASSERT_TRUE(wrapper->parameters().find("k"));
    EXPECT_EQ(wrapper->parameters().find("k")->value, "3");
    EXPECT_EQ(wrapper->parameters().find("y0")->value, "0.5");
    ASSERT_TRUE(wrapper->parameters().find("u#Value"));
}

TEST_F(FmuImport, EditingThePathDeclaresThePortsOnce)
{
    System root;
    root.modelDirectory = dir.path().string();
    root.addComponent(ComponentFactory::instance().create("FMIWrapper"));
    Component& wrapper = *root.component("FMIWrapper");
    EXPECT_FALSE(wrapper.port("u"));
    Parameter& path = *wrapper.parameters().find("path");
    ASSERT_TRUE(assignParameter(wrapper, path, "integrator.fmu"));
    EXPECT_TRUE(wrapper.port("u"));
    EXPECT_TRUE(wrapper.port("y"));
    EXPECT_TRUE(wrapper.parameters().find("k"));
    // Another FMU would change the ports under their connections: refused, the path kept.
    writeIntegratorFmu(dir.path() / "other.fmu");
    const Status refused = assignParameter(wrapper, path, "other.fmu");
    EXPECT_EQ(refused.code(), StatusCode::InvalidParameter);
    EXPECT_NE(refused.message().find("use a new component"), std::string::npos) << refused.message();
    EXPECT_EQ(path.value, "integrator.fmu");
}

TEST_F(FmuImport, RunMatchesTheExactDiscreteSolution)
{
    LoadedModel loaded = loadHmfFile(modelFile().string());
    ASSERT_FALSE(loaded.hasErrors()) << loaded.firstError();
    // compile(const Model&) runs a copy: the copy loads the FMU as well.
    Model model(std::move(loaded.root));
    Result<Simulation> sim = compile(model);
    ASSERT_TRUE(sim) << describe(sim.status());
    ASSERT_TRUE(sim->run()) << "run failed";
    const ResultView results = sim->results();
    const std::vector<double> time(results.time().begin(), results.time().end());
    const auto u = results.data("Step#out#Value");
    const auto y = results.data("Integrator#y#Value");
    ASSERT_TRUE(u && y);
    expectExactSolution(time, *u, *y);

    // Runs again after a reset, with a new parameter value reaching the FMU.
    ASSERT_TRUE(sim->reset());
    ASSERT_TRUE(sim->setParameter("Integrator.y0", "-1"));
    ASSERT_TRUE(sim->run());
    const auto again = sim->results().data("Integrator#y#Value");
    ASSERT_TRUE(again);
    EXPECT_NEAR(again->back(), y->back() - 1.5, 1e-12);
}

TEST_F(FmuImport, TheFmusLogReachesTheComponentsMessages)
{
    LoadedModel loaded = loadHmfFile(modelFile().string());
    ASSERT_FALSE(loaded.hasErrors()) << loaded.firstError();
    Result<Simulation> sim = compile(*loaded.root, {});
    ASSERT_TRUE(sim) << describe(sim.status());
    ASSERT_TRUE(sim->run());
    bool found = false;
    for (const Message& m : loaded.root->messages())
        found |= m.text.find("integrator Integrator instantiated") != std::string::npos;
    EXPECT_TRUE(found);
}

TEST_F(FmuImport, CommandLineRunMatchesTheExactDiscreteSolution)
{
    const fs::path csv = dir.path() / "out.csv";
    const std::string command = std::string(TLMHUB_CLI) + " run '" + modelFile().string() + "' --csv '" +
                                csv.string() + "' > '" + (dir.path() / "cli.log").string() + "' 2>&1";
    ASSERT_EQ(std::system(command.c_str()), 0) << readFile(dir.path() / "cli.log");
    std::ifstream in(csv);
    std::string header;
    std::getline(in, header);
    // Columns: time first, then the variables in export order; find ours by name.
    std::vector<std::string> names;
    std::stringstream headerStream(header);
    for (std::string name; std::getline(headerStream, name, ',');) names.push_back(name);
    const auto column = [&](const std::string& needle) {
        for (std::size_t i = 0; i < names.size(); ++i)
            if (names[i].find(needle) != std::string::npos) return i;
        ADD_FAILURE() << "no column " << needle << " in " << header;
        return std::size_t{0};
    };
    const std::size_t uColumn = column("Step#out#Value"), yColumn = column("Integrator#y#Value");
    std::vector<double> time, u, y;
    for (std::string line; std::getline(in, line);) {
        std::vector<double> row;
        std::stringstream lineStream(line);
        for (std::string cell; std::getline(lineStream, cell, ',');) row.push_back(std::stod(cell));
        ASSERT_EQ(row.size(), names.size());
        time.push_back(row[0]);
        u.push_back(row[uColumn]);
        y.push_back(row[yColumn]);
    }
    expectExactSolution(time, u, y);
}

} // namespace
} // namespace tlmhub::fmu::test
