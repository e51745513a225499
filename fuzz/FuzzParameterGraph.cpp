// Fuzzes the work one evaluation pass does over a graph of parameter references (issue 37
// H1): the input describes up to 300 system parameters p0, p1, ..., each a number or an
// expression naming up to four of them (itself and loops included), and every parameter is
// evaluated in one pass with a small budget. Must hold: the pass never evaluates more
// expressions than its budget; when every parameter evaluates, it evaluated each expression
// parameter at most once.
#include "core/ParameterEvaluator.h"
#include "core/System.h"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

namespace {

constexpr std::size_t kMaxParameters = 300;   // past the evaluator's reference depth of 250
constexpr std::size_t kBudget = 500;
constexpr const char* kOperators[] = {"+", "-", "*", "/"};

// Reads the input a byte at a time; past its end, zeros.
struct Bytes {
    const std::uint8_t* data;
    std::size_t size, at = 0;
    unsigned next() { return at < size ? data[at++] : 0; }
};

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    Bytes in{data, size};
    const std::size_t count = 1 + (in.next() << 8 | in.next()) % kMaxParameters;
    tlmhub::System root;
    std::size_t expressions = 0;
    for (std::size_t i = 0; i < count; ++i) {
        const unsigned shape = in.next();
        const unsigned references = shape % 5;
        std::string value;
        if (references == 0) {
            value = std::to_string(shape / 5);
        } else {
            ++expressions;
            for (unsigned r = 0; r < references; ++r) {
                if (r > 0) value += kOperators[in.next() % 4];
                value += "p" + std::to_string((in.next() << 8 | in.next()) % count);
            }
        }
        root.setSystemParameter("p" + std::to_string(i), value, "double", "", "", false);
    }
    tlmhub::ParameterEvaluator::Pass pass(kBudget);
    bool allEvaluated = true;
    for (const auto& param : root.parameters().all())
        allEvaluated = tlmhub::ParameterEvaluator::evaluate(root, *param, pass).isOk() && allEvaluated;
    if (pass.evaluations > kBudget) std::abort();
    if (allEvaluated && pass.evaluations > expressions) std::abort();
    return 0;
}
