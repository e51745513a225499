// nlohmann/json's parser and serializer, compiled with optimisation, for the programs that
// parse or write much JSON with code built at -O0: the test programs (test code builds at -O0,
// it compiles twice as fast) and, under the sanitizers, the server and the CLI (their
// libraries build at -O0 there; server/CMakeLists.txt, cli/CMakeLists.txt).
//
// The template code a -O0 file instantiates is -O0 code too. Of the copies of one inline
// definition the linker keeps the first, and this file is the first object on those programs'
// link lines, so every parse and dump in them runs this file's optimised copy. Under ASan a
// test that opened a 10 MB model five times spent half its CPU parsing the replies at -O0
// (Responsiveness.OpeningLargeModels…: 111 s of CPU before, 49 s after).
#include "server/OptimisedJson.h"

using tlmhub::json_inputs::CharsInput;
using tlmhub::json_inputs::StringInput;

template class nlohmann::basic_json<>;
template class nlohmann::detail::lexer<nlohmann::json, StringInput>;
template class nlohmann::detail::parser<nlohmann::json, StringInput>;
template class nlohmann::detail::lexer<nlohmann::json, CharsInput>;
template class nlohmann::detail::parser<nlohmann::json, CharsInput>;
template class nlohmann::detail::json_sax_dom_parser<nlohmann::json>;
template class nlohmann::detail::json_sax_dom_callback_parser<nlohmann::json>;
template class nlohmann::detail::serializer<nlohmann::json>;
