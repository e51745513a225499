#include "server/jobs/FrameSource.h"

#include "core/System.h"

#include <algorithm>

namespace tlmhub::server {

namespace {

void appendRange(const std::vector<double>& v, std::size_t from, std::size_t to, std::vector<double>& out)
{
    to = std::min(to, v.size());
    if (from < to) out.insert(out.end(), v.begin() + static_cast<std::ptrdiff_t>(from),
                              v.begin() + static_cast<std::ptrdiff_t>(to));
}

} // namespace

std::optional<std::size_t> FrameSource::find(const std::string& name) const
{
    auto it = mIndex.find(name);
    if (it == mIndex.end()) return std::nullopt;
    return it->second;
}

void FrameSource::setNames(std::vector<std::string> names)
{
    mNames = std::move(names);
    mIndex.clear();
    for (std::size_t i = 0; i < mNames.size(); ++i) mIndex.emplace(mNames[i], i);
}

TableFrameSource::TableFrameSource(const ResultTable& table) : mTable(table)
{
    std::vector<std::string> names;
    for (const auto& c : table.columns) names.push_back(c.name);
    setNames(std::move(names));
}

void TableFrameSource::appendTime(std::size_t from, std::size_t to, std::vector<double>& out) const
{
    appendRange(mTable.time, from, to, out);
}

std::size_t TableFrameSource::count(std::size_t column) const
{
    return std::min(mTable.columns[column].data.size(), mTable.time.size());
}

void TableFrameSource::appendData(std::size_t column, std::size_t from, std::size_t to,
                                  std::vector<double>& out) const
{
    appendRange(mTable.columns[column].data, from, std::min(to, count(column)), out);
}

LiveFrameSource::LiveFrameSource(const System& root) : mRoot(root), mVariables(listLoggedVariables(root))
{
    std::vector<std::string> names;
    for (const auto& v : mVariables) names.push_back(v.fullName);
    setNames(std::move(names));
}

std::size_t LiveFrameSource::timeCount() const
{
    return std::min(mRoot.numLoggedSamples(), mRoot.logTime().size());
}

void LiveFrameSource::appendTime(std::size_t from, std::size_t to, std::vector<double>& out) const
{
    appendRange(mRoot.logTime(), from, std::min(to, timeCount()), out);
}

std::size_t LiveFrameSource::count(std::size_t column) const
{
    return std::min(mVariables[column].owner->numLoggedSamples(), timeCount());
}

void LiveFrameSource::appendData(std::size_t column, std::size_t from, std::size_t to,
                                 std::vector<double>& out) const
{
    const LoggedVariable& v = mVariables[column];
    appendLoggedData(*v.port, v.slot, from, std::min(to, count(column)), out);
}

} // namespace tlmhub::server
