#include "server/studies/ParameterSampling.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace tlmhub::server {

namespace {

std::size_t saturatingProduct(std::size_t a, std::size_t b)
{
    if (a != 0 && b > std::numeric_limits<std::size_t>::max() / a) return std::numeric_limits<std::size_t>::max();
    return a * b;
}

std::size_t axisLength(const SweepAxis& axis)
{
    if (const auto* list = std::get_if<std::vector<double>>(&axis.values)) return list->size();
    return std::get<SweepRange>(axis.values).steps;
}

// Value `i` of a range; std::lerp is exact at both ends and monotonic between them.
double rangeValue(const SweepRange& range, std::size_t i)
{
    if (range.steps <= 1) return range.from;
    return std::lerp(range.from, range.to, static_cast<double>(i) / static_cast<double>(range.steps - 1));
}

double axisValue(const SweepAxis& axis, std::size_t i)
{
    if (const auto* list = std::get_if<std::vector<double>>(&axis.values)) return (*list)[i];
    return rangeValue(std::get<SweepRange>(axis.values), i);
}

double randomAxisValue(const SweepAxis& axis, std::mt19937_64& random)
{
    const double u = uniformUnit(random);
    if (const auto* list = std::get_if<std::vector<double>>(&axis.values)) {
        // u < 1, but u × size can round up to size.
        const auto i = static_cast<std::size_t>(u * static_cast<double>(list->size()));
        return (*list)[std::min(i, list->size() - 1)];
    }
    const auto& range = std::get<SweepRange>(axis.values);
    return range.from + (range.to - range.from) * u;
}

} // namespace

std::vector<double> axisValues(const SweepAxis& axis)
{
    std::vector<double> values(axisLength(axis));
    for (std::size_t i = 0; i < values.size(); ++i) values[i] = axisValue(axis, i);
    return values;
}

std::size_t sweepSize(const std::vector<SweepAxis>& axes, SweepMode mode, std::size_t samples)
{
    if (axes.empty()) return 0;
    for (const auto& axis : axes)
        if (axisLength(axis) == 0) return 0;
    switch (mode) {
    case SweepMode::Grid: {
        std::size_t size = 1;
        for (const auto& axis : axes) size = saturatingProduct(size, axisLength(axis));
        return size;
    }
    case SweepMode::List: {
        const std::size_t length = axisLength(axes.front());
        for (const auto& axis : axes)
            if (axisLength(axis) != length) return 0;
        return length;
    }
    case SweepMode::Random:
        return samples;
    }
    return 0;
}

std::vector<double> sweepPoint(const std::vector<SweepAxis>& axes, SweepMode mode, std::size_t index,
                               std::uint64_t seed)
{
    std::vector<double> point(axes.size());
    switch (mode) {
    case SweepMode::Grid:
        // Mixed radix with the last axis as the lowest digit, so the first varies slowest.
        for (std::size_t a = axes.size(); a-- > 0;) {
            const std::size_t length = axisLength(axes[a]);
            point[a] = axisValue(axes[a], index % length);
            index /= length;
        }
        break;
    case SweepMode::List:
        for (std::size_t a = 0; a < axes.size(); ++a) point[a] = axisValue(axes[a], index);
        break;
    case SweepMode::Random: {
        auto random = indexedGenerator(seed, index);
        for (std::size_t a = 0; a < axes.size(); ++a) point[a] = randomAxisValue(axes[a], random);
        break;
    }
    }
    return point;
}

std::vector<double> monteCarloPoint(const std::vector<RandomParameter>& parameters, std::size_t index,
                                    std::uint64_t seed)
{
    auto random = indexedGenerator(seed, index);
    std::vector<double> point(parameters.size());
    for (std::size_t p = 0; p < parameters.size(); ++p) {
        const Distribution& d = parameters[p].distribution;
        point[p] = d.kind == Distribution::Kind::Normal ? d.a + d.b * standardNormal(random)
                                                        : d.a + (d.b - d.a) * uniformUnit(random);
    }
    return point;
}

std::uint64_t splitMix64(std::uint64_t x)
{
    x += 0x9e3779b97f4a7c15ULL;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
    return x ^ (x >> 31);
}

std::mt19937_64 indexedGenerator(std::uint64_t seed, std::size_t index)
{
    // Mixing twice: neighbouring seeds and neighbouring indices give unrelated generator seeds.
    return std::mt19937_64(splitMix64(splitMix64(seed) + static_cast<std::uint64_t>(index)));
}

double uniformUnit(std::mt19937_64& random)
{
    return static_cast<double>(random() >> 11) * 0x1.0p-53;
}

double standardNormal(std::mt19937_64& random)
{
    // 1 - u is in (0, 1], so the logarithm is finite.
    const double u1 = 1.0 - uniformUnit(random);
    const double u2 = uniformUnit(random);
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

} // namespace tlmhub::server
