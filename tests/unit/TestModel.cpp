// Model: compile(const Model&) runs a copy and leaves the model as it was; the copy is what
// saving and reloading the model would give.
#include "TestHelpers.h"

#include "core/Model.h"
#include "core/ParameterPath.h"
#include "core/hmf/HmfLoader.h"

#include <algorithm>
#include <filesystem>
#include <thread>

using namespace tlmhub;
using namespace tlmhub::test;

namespace {

// Every shared model that loads (the ones that must fail are in tests/models/outcomes.txt).
std::vector<std::string> sharedModels()
{
    std::vector<std::string> paths;
    for (const char* dir : {"/hopsan-models", "/bench-models"})
        for (const auto& entry : std::filesystem::recursive_directory_iterator(sharedDir() + dir))
            if (entry.path().extension() == ".hmf") paths.push_back(entry.path().string());
    std::sort(paths.begin(), paths.end());
    return paths;
}

Model loadModel(const std::string& path)
{
    LoadedModel loaded = loadHmfFile(path);
    EXPECT_TRUE(loaded.root) << path << ": " << loaded.firstError();
    return Model(std::move(loaded.root));
}

} // namespace

TEST(Model, ACopySavesAsTheModelDoesForEverySharedModel)
{
    const std::vector<std::string> paths = sharedModels();
    ASSERT_GT(paths.size(), 100u) << "shared models missing under " << sharedDir();
    for (const std::string& path : paths) {
        LoadedModel loaded = loadHmfFile(path);
        if (!loaded.root) continue;
        const Model model(std::move(loaded.root));
        const Result<Model> copy = model.copy();
        ASSERT_TRUE(copy) << path << ": " << copy.status().message();
        EXPECT_EQ(copy->toHmf(), model.toHmf()) << path;
    }
}

namespace {

const std::string positionServo = "/hopsan-models/Example Models/Position Servo.hmf";

std::vector<std::vector<double>> runColumns(Result<Simulation> compiled)
{
    const std::optional<Simulation> sim = runToStop(std::move(compiled));
    return sim ? loggedColumns(sim->results()) : std::vector<std::vector<double>>{};
}

} // namespace

TEST(Model, CompilingRunsACopyAndLeavesTheModelAsItWas)
{
    Model model = loadModel(sharedDir() + positionServo);
    const std::string before = model.toHmf();
    const auto first = runColumns(compile(model));
    ASSERT_GT(first.size(), 1u);
    EXPECT_EQ(model.toHmf(), before);
    // The model's own nodes never ran: compiling it again gives the same run.
    EXPECT_TRUE(runColumns(compile(model)) == first);
    EXPECT_TRUE(runColumns(compile(std::move(model))) == first);
}

TEST(Model, EditingTheModelLeavesACompiledSimulationAsItWas)
{
    Model model = loadModel(sharedDir() + positionServo);
    Result<Simulation> compiled = compile(model);
    ASSERT_TRUE(compiled) << compiled.status().message();
    ASSERT_TRUE(isOk(setParameterValue(model.root(), "Mass.m", "500")));
    const auto edited = runColumns(compile(model));
    const auto unedited = runColumns(std::move(compiled));
    ASSERT_GT(edited.size(), 1u);
    EXPECT_TRUE(unedited == runColumns(compile(loadModel(sharedDir() + positionServo))));
    EXPECT_FALSE(edited == unedited);
}

TEST(Model, OneModelCompilesAndRunsOnSeveralThreadsAtOnce)
{
    const Model model = loadModel(sharedDir() + positionServo);
    const auto alone = runColumns(compile(model));
    ASSERT_GT(alone.size(), 1u);
    std::vector<std::vector<std::vector<double>>> results(4);
    std::vector<std::thread> threads;
    for (auto& result : results) threads.emplace_back([&model, &result] { result = runColumns(compile(model)); });
    for (auto& t : threads) t.join();
    for (const auto& result : results) EXPECT_TRUE(result == alone);
}

// A component type made outside the factory cannot be made again for a copy.
class Unregistered : public ComponentSignal {};

TEST(Model, ACopyNeedsEveryComponentTypeFromTheFactory)
{
    Model model;
    auto made = std::make_unique<Unregistered>();
    made->setNameRaw("Custom");
    made->setTypeName("CustomType");
    model.root().addComponent(std::move(made));
    const Result<Model> copy = model.copy();
    ASSERT_FALSE(copy);
    EXPECT_EQ(copy.status().code(), StatusCode::UnknownComponentType);
    EXPECT_EQ(copy.status().path(), "Custom");
    const Result<Simulation> compiled = compile(model);
    ASSERT_FALSE(compiled);
    EXPECT_EQ(compiled.status().code(), StatusCode::UnknownComponentType);
}
