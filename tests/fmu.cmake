# FMU tests (label fmu): one executable from tests/fmu/*.cpp; what the export side and the
# import side build for it (the runtime library, the hand-written test FMU) is in their own
# files.
file(GLOB TLMHUB_FMU_TEST_SOURCES CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/fmu/*.cpp)
tlmhub_threads_only_sources(TLMHUB_FMU_TEST_SOURCES)
if(TLMHUB_FMU_TEST_SOURCES)
  add_executable(tlmhub-fmu-tests ${TLMHUB_FMU_TEST_SOURCES})
  target_link_libraries(tlmhub-fmu-tests PRIVATE tlmhub::core tlmhub::fmu GTest::gtest GTest::gtest_main)
  target_compile_options(tlmhub-fmu-tests PRIVATE ${TLMHUB_HARNESS_OPTIONS})
  target_compile_definitions(tlmhub-fmu-tests PRIVATE TLMHUB_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
                             TLMHUB_SHARED_DIR="${TLMHUB_SHARED_DIR}"
                             TLMHUB_CLI="$<TARGET_FILE:tlmhub-cli>")
  # The tests export, import and run models through the CLI too, as a user does.
  add_dependencies(tlmhub-fmu-tests tlmhub-cli)
  # FmuChecker starts the CLI once in SetUpTestSuite for all its tests: one ctest.
  tlmhub_add_suite_tests(tlmhub-fmu-tests SUITES FmuChecker LABELS fmu PROPERTIES TIMEOUT 300)
  tlmhub_discover_tests(tlmhub-fmu-tests SET other FILTER "-FmuChecker.*" LABELS fmu PROPERTIES TIMEOUT 300)
  include(${CMAKE_CURRENT_SOURCE_DIR}/fmu/export.cmake)
  include(${CMAKE_CURRENT_SOURCE_DIR}/fmu/import.cmake)
endif()
