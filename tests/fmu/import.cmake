# Import side of the FMU tests.
# The hand-written test FMUs' libraries (tests/fmu/handwritten/): integrator.so, a copy of
# it without fmi2DoStep for the broken-FMU tests, and pressure_source.so (a power port). The
# tests zip them with their modelDescription.xml into .fmu files themselves (libzip), as
# broken variants need. The C sources compile as C++ with the project's one compiler.
set(TLMHUB_TEST_FMU_SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/fmu/handwritten)
set_source_files_properties(${TLMHUB_TEST_FMU_SOURCES}/integrator.c ${TLMHUB_TEST_FMU_SOURCES}/pressure_source.c
                            PROPERTIES LANGUAGE CXX)
foreach(variant integrator integrator_without_do_step pressure_source)
  set(source integrator.c)
  if(variant STREQUAL "pressure_source")
    set(source pressure_source.c)
  endif()
  add_library(tlmhub-test-fmu-${variant} MODULE ${TLMHUB_TEST_FMU_SOURCES}/${source})
  set_target_properties(tlmhub-test-fmu-${variant} PROPERTIES PREFIX "" OUTPUT_NAME ${variant}
                        LIBRARY_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/test-fmus CXX_VISIBILITY_PRESET hidden)
  target_include_directories(tlmhub-test-fmu-${variant} PRIVATE ${PROJECT_SOURCE_DIR})
  target_compile_options(tlmhub-test-fmu-${variant} PRIVATE -Wno-unused-parameter)
  add_dependencies(tlmhub-fmu-tests tlmhub-test-fmu-${variant})
endforeach()
target_compile_definitions(tlmhub-test-fmu-integrator_without_do_step PRIVATE TLMHUB_TEST_WITHOUT_DO_STEP)
target_compile_definitions(tlmhub-fmu-tests PRIVATE
  TLMHUB_TEST_FMU_LIBRARY="$<TARGET_FILE:tlmhub-test-fmu-integrator>"
  TLMHUB_TEST_FMU_LIBRARY_WITHOUT_DO_STEP="$<TARGET_FILE:tlmhub-test-fmu-integrator_without_do_step>"
  TLMHUB_TEST_FMU_LIBRARY_PRESSURE_SOURCE="$<TARGET_FILE:tlmhub-test-fmu-pressure_source>")
