#pragma once
// The logged results of one run as plain columns: the time vector and one column per logged
// variable, named as HopsanCLI names them ("Sub$Comp#Port#Var"). The CLI's --csv output and
// the server's stored job results are both written from this one type, so they agree byte
// for byte.
#include <nlohmann/json.hpp>

#include <cstddef>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace tlmhub {

class ResultView;
class System;

struct ResultColumn {
    std::string name;
    std::string unit;
    std::vector<double> data;   // at most time.size() samples; shorter if logging started late
};

struct ResultTable {
    std::vector<double> time;   // s
    std::vector<ResultColumn> columns;

    // Copies the logged samples of a run in the view's (HopsanCLI's) order.
    static ResultTable fromView(const ResultView& view);
    static ResultTable fromSystem(const System& root);

    // Header "time,<names>", one row per time sample, numbers as "%.17g", an empty cell where
    // a column has fewer samples. `variables` picks and orders columns (unknown names are
    // skipped); empty means all.
    std::string toCsv(const std::vector<std::string>& variables = {}) const;
    // The same text handed to `sink` in pieces of about 64 KiB, so a large table can be
    // written or hashed without holding its whole CSV in memory.
    void writeCsv(const std::function<void(std::string_view)>& sink,
                  const std::vector<std::string>& variables = {}) const;
    // {"time":[...],"variables":[{"name","unit","data":[...]}]}; same selection rule.
    nlohmann::json toJson(const std::vector<std::string>& variables = {}) const;

    // Compact binary form for storage: little-endian doubles, length-prefixed strings.
    std::string serialize() const;
    // False (and `out` unchanged) if `bytes` is not a complete serialized table.
    static bool deserialize(const std::string& bytes, ResultTable& out);
    // Size of serialize()'s output, computed without serializing.
    std::size_t byteSize() const;

    bool hasColumn(const std::string& name) const;
    const ResultColumn* column(const std::string& name) const;
};

} // namespace tlmhub
