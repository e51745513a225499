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

std::vector<double> ResultView::data(std::size_t index) const
{
    const LoggedVariable& v = mVariables[index];
    const std::size_t count = std::min(v.owner->numLoggedSamples(), numSamples());
    std::vector<double> out;
    appendLoggedData(*v.port, v.slot, 0, count, out);
    return out;
}

std::optional<std::vector<double>> ResultView::data(std::string_view name) const
{
    const auto index = indexOf(name);
    if (!index) return std::nullopt;
    return data(*index);
}

} // namespace tlmhub
