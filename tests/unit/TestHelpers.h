#pragma once
// Small helpers shared by the unit tests: build systems through the string API, run them.
#include "core/ComponentFactory.h"
#include "core/NodeTypes.h"
#include "core/Results.h"
#include "core/Simulation.h"
#include "core/System.h"

#include <gtest/gtest.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace tlmhub::test {

inline std::string add(System& s, const std::string& type, const std::string& name)
{
    auto c = ComponentFactory::instance().create(type);
    EXPECT_TRUE(c) << "unknown type " << type;
    if (!c) return {};
    c->setNameRaw(name);
    return s.addComponent(std::move(c));
}

// Passes for an ok status; else fails showing its code and message.
inline ::testing::AssertionResult isOk(const Status& status)
{
    if (status) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << describe(status);
}

inline void connectOk(System& s, const std::string& a, const std::string& pa, const std::string& b,
                      const std::string& pb)
{
    ASSERT_TRUE(isOk(s.connect(a, pa, b, pb)));
}

inline void setParam(System& s, const std::string& comp, const std::string& name, const std::string& value)
{
    Component* c = s.component(comp);
    ASSERT_TRUE(c) << comp;
    Parameter* p = c->parameters().find(name);
    ASSERT_TRUE(p) << comp << "." << name;
    p->value = value;
}

// Compiles and runs `s` from t0 to t1; false (and a test failure for a compile error) if it
// does not get there. The logs stay readable through `s` afterwards.
inline bool run(System& s, double t0, double t1, double ts, std::size_t samples)
{
    Result<Simulation> sim = compile(s, {t0, t1, ts, samples});
    if (!sim) {
        ADD_FAILURE() << describe(sim.status());
        return false;
    }
    return sim->run().isOk();
}

// Runs a compiled simulation to its stop time. A compile or run error is a test failure
// naming its status; nullopt if it did not compile.
inline std::optional<Simulation> runToStop(Result<Simulation> compiled, const RunOptions& options = {})
{
    if (!compiled) {
        ADD_FAILURE() << describe(compiled.status());
        return std::nullopt;
    }
    EXPECT_TRUE(isOk(compiled->run(options)));
    return std::move(*compiled);
}

// The logged samples of one node variable ("Pressure") at a component's port, after a run.
inline std::vector<double> loggedSlot(System& s, const std::string& comp, const std::string& port,
                                      const std::string& variable)
{
    Port* p = s.component(comp)->port(port);
    return loggedData(*p, nodeVariableIndex(p->nodeType(), variable), s.numLoggedSamples());
}

// The logged time, then every logged variable in list order: what two runs compare.
inline std::vector<std::vector<double>> loggedColumns(const ResultView& results)
{
    std::vector<std::vector<double>> columns{{results.time().begin(), results.time().end()}};
    for (std::size_t i = 0; i < results.numVariables(); ++i) columns.push_back(results.data(i));
    return columns;
}

inline std::string sharedDir()
{
    return std::string(TLMHUB_SOURCE_DIR) + "/../shared";
}

} // namespace tlmhub::test
