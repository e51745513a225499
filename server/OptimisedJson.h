#pragma once
// nlohmann/json's parser, serializer and value type as instantiated once, optimised, in
// OptimisedJson.cpp. Declared here as explicit instantiations defined elsewhere, the files that
// include this header compile no copy of their member functions at -O0 (clang emits none), and
// call the optimised one. The server's precompiled header (clang: the sanitizer builds)
// includes it: there it took a fifth to a third off each server file's compile time.
#include <nlohmann/json.hpp>

#include <string>

namespace tlmhub::json_inputs {
using StringInput = nlohmann::detail::iterator_input_adapter<std::string::const_iterator>;
using CharsInput = nlohmann::detail::iterator_input_adapter<const char*>;
} // namespace tlmhub::json_inputs

extern template class nlohmann::basic_json<>;
extern template class nlohmann::detail::lexer<nlohmann::json, tlmhub::json_inputs::StringInput>;
extern template class nlohmann::detail::parser<nlohmann::json, tlmhub::json_inputs::StringInput>;
extern template class nlohmann::detail::lexer<nlohmann::json, tlmhub::json_inputs::CharsInput>;
extern template class nlohmann::detail::parser<nlohmann::json, tlmhub::json_inputs::CharsInput>;
extern template class nlohmann::detail::json_sax_dom_parser<nlohmann::json>;
extern template class nlohmann::detail::json_sax_dom_callback_parser<nlohmann::json>;
extern template class nlohmann::detail::serializer<nlohmann::json>;
