#pragma once
// The examples in protocol/README.md, which the protocol tests check against the schema and
// the generated message structs.
#include "TestFiles.h"

#include <nlohmann/json.hpp>

#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace tlmhub::test {

// A ```json block of protocol/README.md preceded by a marker line:
// <!-- message -->, <!-- message reply:TYPE --> or <!-- rest: Definition -->.
struct ReadmeExample {
    std::string kind;       // "message" or "rest"
    std::string argument;   // "reply:TYPE", a definition name, or empty
    std::size_t line = 0;
    nlohmann::json value;
};

inline std::vector<ReadmeExample> readmeExamples()
{
    std::istringstream in(readFile(TLMHUB_SOURCE_DIR "/protocol/README.md"));
    std::vector<std::string> lines;
    for (std::string l; std::getline(in, l);) lines.push_back(l);
    const std::regex marker(R"(^<!-- (message|rest)(?:[: ]\s*(\S+))? -->$)");
    std::vector<ReadmeExample> out;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        std::smatch m;
        if (!std::regex_match(lines[i], m, marker)) continue;
        ReadmeExample e{m[1], m[2], i + 1, {}};
        EXPECT_TRUE(i + 1 < lines.size() && lines[i + 1] == "```json") << "README line " << e.line;
        std::string text;
        std::size_t j = i + 2;
        for (; j < lines.size() && lines[j] != "```"; ++j) text += lines[j] + "\n";
        e.value = nlohmann::json::parse(text, nullptr, false);
        EXPECT_FALSE(e.value.is_discarded()) << "README line " << e.line << ": not JSON";
        out.push_back(std::move(e));
        i = j;
    }
    return out;
}

} // namespace tlmhub::test
