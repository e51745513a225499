#include "core/ResultView.h"

#include <algorithm>

namespace tlmhub {

ResultView::ResultView(const System& root) : mRoot(&root), mVariables(listLoggedVariables(root)) {}

std::span<const double> ResultView::time() const
{
    const auto& t = mRoot->logTime();
    return {t.data(), std::min(mRoot->numLoggedSamples(), t.size())};
}

std::optional<std::size_t> ResultView::indexOf(std::string_view name) const
{
    for (std::size_t i = 0; i < mVariables.size(); ++i)
        if (mVariables[i].fullName == name) return i;
    return std::nullopt;
}

std::size_t ResultView::count(std::size_t index) const
{
    const LoggedVariable& v = mVariables[index];
    const Node* node = v.port->node();
    if (!node || node->logData.empty()) return 0;
    return std::min({v.owner->numLoggedSamples(), numSamples(), node->logData.samples()});
}

std::vector<double> ResultView::data(std::size_t index) const
{
    std::vector<double> out(count(index));
    double* to = out.data();
    copyData({&index, 1}, {&to, 1});
    return out;
}

void ResultView::copyData(std::span<const std::size_t> indices, std::span<double* const> out) const
{
    // 64 rows of a few kB each stay in the cache while every column takes its part.
    constexpr std::size_t kRowsPerBlock = 64;
    struct Column {
        const double* first;
        std::size_t stride, count;
        double* out;
    };
    std::vector<Column> columns;
    std::size_t rows = 0;
    for (std::size_t k = 0; k < indices.size(); ++k) {
        const std::size_t n = count(indices[k]);
        if (n == 0) continue;
        const LoggedVariable& v = mVariables[indices[k]];
        const LogBuffer& log = v.port->node()->logData;
        columns.push_back({log.first(static_cast<std::size_t>(v.slot)), log.stride(), n, out[k]});
        rows = std::max(rows, n);
    }
    for (std::size_t from = 0; from < rows; from += kRowsPerBlock) {
        for (const Column& c : columns) {
            const std::size_t to = std::min(c.count, from + kRowsPerBlock);
            for (std::size_t i = from; i < to; ++i) c.out[i] = c.first[i * c.stride];
        }
    }
}

std::optional<std::vector<double>> ResultView::data(std::string_view name) const
{
    const auto index = indexOf(name);
    if (!index) return std::nullopt;
    return data(*index);
}

} // namespace tlmhub
