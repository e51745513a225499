# tlmhub-cli remote (label cli): its parts without a server (options, study requests,
# credentials), and the binary itself against a real tlmhub-server on loopback, over http
# and over https through tests/tools/tls_proxy.py.
if(TARGET tlmhub-server)
  file(GLOB TLMHUB_CLI_TEST_SOURCES CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/cli/*.cpp)
  tlmhub_threads_only_sources(TLMHUB_CLI_TEST_SOURCES)
  add_executable(tlmhub-cli-tests $<TARGET_OBJECTS:tlmhub_optimised_json> ${TLMHUB_CLI_TEST_SOURCES})
  target_include_directories(tlmhub-cli-tests PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
  target_link_libraries(tlmhub-cli-tests PRIVATE tlmhub_test_support tlmhub_cli_remote GTest::gtest GTest::gtest_main)
  target_compile_options(tlmhub-cli-tests PRIVATE ${TLMHUB_HARNESS_OPTIONS})
  target_compile_definitions(tlmhub-cli-tests PRIVATE TLMHUB_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
                             TLMHUB_SERVER_BIN="$<TARGET_FILE:tlmhub-server>"
                             TLMHUB_CLI_BIN="$<TARGET_FILE:tlmhub-cli>")
  add_dependencies(tlmhub-cli-tests tlmhub-server tlmhub-cli)
  tlmhub_discover_tests(tlmhub-cli-tests SET all LABELS cli PROPERTIES TIMEOUT 180)
endif()
