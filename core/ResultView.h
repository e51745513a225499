#pragma once
// The logged results of a run, read in place: the time vector and every logged variable by
// index or by Hopsan's name ("Sub$Comp#Port#Var"), in HopsanCLI's export order. ResultTable,
// the CLI, validation and the server read results through it. Valid while the System's logs
// are (until the next start of its Simulation).
#include "core/Results.h"

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace tlmhub {

class ResultView {
public:
    explicit ResultView(const System& root);

    // Time of every sample logged so far.
    std::span<const double> time() const;
    std::size_t numSamples() const { return time().size(); }

    std::size_t numVariables() const { return mVariables.size(); }
    const LoggedVariable& variable(std::size_t index) const { return mVariables[index]; }
    const std::vector<LoggedVariable>& variables() const { return mVariables; }
    std::optional<std::size_t> indexOf(std::string_view name) const;

    // The samples of one variable logged so far (a subsystem that started logging late has
    // fewer than numSamples()).
    std::vector<double> data(std::size_t index) const;
    std::optional<std::vector<double>> data(std::string_view name) const;
    // Samples logged so far (as data() gives them) of the variables `indices` into out[k],
    // which has room for them. The log keeps a row per sample, so one column strides across
    // every row; many columns are copied a block of rows at a time, so each row is fetched
    // from memory once, not once per column.
    std::size_t count(std::size_t index) const;
    void copyData(std::span<const std::size_t> indices, std::span<double* const> out) const;

private:
    const System* mRoot;
    std::vector<LoggedVariable> mVariables;
};

} // namespace tlmhub
