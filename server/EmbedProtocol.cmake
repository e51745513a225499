# Writes OUTPUT: a C++ file holding every PROTOCOL_DIR/*.json as a string, looked up by file name.
file(GLOB files "${PROTOCOL_DIR}/*.json")
list(SORT files)
set(body "// Generated from protocol/*.json by server/EmbedProtocol.cmake. Do not edit.\n#include \"server/protocol/EmbeddedProtocol.h\"\n\nnamespace tlmhub::server {\n\nconst std::vector<EmbeddedFile>& embeddedProtocolFiles()\n{\n    static const std::vector<EmbeddedFile> files = {\n")
foreach(f IN LISTS files)
  get_filename_component(name "${f}" NAME)
  file(READ "${f}" content HEX)
  string(REGEX REPLACE "([0-9a-f][0-9a-f])" "\\\\x\\1" escaped "${content}")
  # Split into chunks so no single literal gets too long for the compiler.
  string(REGEX REPLACE "((\\\\x[0-9a-f][0-9a-f]){200})" "\\1\"\n\"" escaped "${escaped}")
  string(APPEND body "        {\"${name}\", std::string(\"${escaped}\")},\n")
endforeach()
string(APPEND body "    };\n    return files;\n}\n\n} // namespace tlmhub::server\n")
file(WRITE "${OUTPUT}" "${body}")
