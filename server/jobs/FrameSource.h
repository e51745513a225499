#pragma once
// Where streamed frames read their samples: a run in progress (straight from the core's log
// buffers, on the job's thread) or a finished ResultTable. Both name and order their columns
// like ResultTable::fromSystem, so frames and the stored result agree sample for sample.
#include "core/ResultTable.h"
#include "core/Results.h"

#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

namespace tlmhub::server {

class FrameSource {
public:
    virtual ~FrameSource() = default;

    // Column names in ResultTable order.
    const std::vector<std::string>& names() const { return mNames; }
    std::optional<std::size_t> find(const std::string& name) const;

    // Samples of the time vector available now.
    virtual std::size_t timeCount() const = 0;
    virtual void appendTime(std::size_t from, std::size_t to, std::vector<double>& out) const = 0;
    // Samples of a column available now (never more than timeCount()).
    virtual std::size_t count(std::size_t column) const = 0;
    virtual void appendData(std::size_t column, std::size_t from, std::size_t to,
                            std::vector<double>& out) const = 0;

protected:
    void setNames(std::vector<std::string> names);

private:
    std::vector<std::string> mNames;
    std::unordered_map<std::string, std::size_t> mIndex;
};

class TableFrameSource final : public FrameSource {
public:
    explicit TableFrameSource(const ResultTable& table);
    std::size_t timeCount() const override { return mTable.time.size(); }
    void appendTime(std::size_t from, std::size_t to, std::vector<double>& out) const override;
    std::size_t count(std::size_t column) const override;
    void appendData(std::size_t column, std::size_t from, std::size_t to,
                    std::vector<double>& out) const override;

private:
    const ResultTable& mTable;
};

// Reads a running System; only valid on the thread that runs it, after initialize().
class LiveFrameSource final : public FrameSource {
public:
    explicit LiveFrameSource(const System& root);
    std::size_t timeCount() const override;
    void appendTime(std::size_t from, std::size_t to, std::vector<double>& out) const override;
    std::size_t count(std::size_t column) const override;
    void appendData(std::size_t column, std::size_t from, std::size_t to,
                    std::vector<double>& out) const override;

private:
    const System& mRoot;
    std::vector<LoggedVariable> mVariables;
};

} // namespace tlmhub::server
