# How the GoogleTest executables become ctests, and their labels.
#
# Every test of a suite named in TLMHUB_THREADS_SUITES gets the label `threads` besides its
# own: it starts threads or child processes, and scripts/test.sh runs the label under TSan.
# The Release stage checks the list (scripts/ci/check_threads_label.py).
include(GoogleTest)

# A regular expression matching the ctest names of the suites in TLMHUB_THREADS_SUITES
# (also `Prefix/Suite.Case/N` of parameterised tests and `Suite.*` of whole suites).
function(tlmhub_threads_regex out)
  list(JOIN TLMHUB_THREADS_SUITES "|" suites)
  set(${out} "^([A-Za-z0-9_]+/)?(${suites})\\." PARENT_SCOPE)
endfunction()

# tlmhub_discover_tests(TARGET SET NAME [FILTER GTEST_FILTER] LABELS LABEL... [PROPERTIES ...])
# One ctest per test case (gtest_discover_tests). gtest_discover_tests writes PROPERTIES out
# unquoted, so a list value ("server;threads") would split into stray property names; the
# labels are set instead by a ctest include file that runs after the discovery, from the
# list of discovered names (named after TARGET and SET, which must be unique per call).
function(tlmhub_discover_tests target)
  cmake_parse_arguments(arg "" "SET;FILTER" "LABELS;PROPERTIES" ${ARGN})
  string(MAKE_C_IDENTIFIER "${target}_${arg_SET}_tests" list)
  set(filter_args "")
  if(arg_FILTER)
    set(filter_args TEST_FILTER "${arg_FILTER}")
  endif()
  gtest_discover_tests(${target} DISCOVERY_TIMEOUT 60 ${filter_args} TEST_LIST ${list}
                       PROPERTIES ${arg_PROPERTIES})
  tlmhub_threads_regex(threads)
  set(labels_file "${CMAKE_CURRENT_BINARY_DIR}/${list}_labels.cmake")
  file(WRITE "${labels_file}"
       "foreach(test IN LISTS ${list})\n"
       "  if(test MATCHES [=[${threads}]=])\n"
       "    set_tests_properties(\"\${test}\" PROPERTIES LABELS \"${arg_LABELS};threads\")\n"
       "  else()\n"
       "    set_tests_properties(\"\${test}\" PROPERTIES LABELS \"${arg_LABELS}\")\n"
       "  endif()\n"
       "endforeach()\n")
  set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES "${labels_file}")
endfunction()

# tlmhub_add_suite_tests(TARGET SUITES SUITE... LABELS LABEL... [PROPERTIES ...])
# One ctest per suite, named `SUITE.*`, for suites whose tests share what their
# SetUpTestSuite starts (a server, its users): one process runs them all, instead of one
# process per test starting it again. scripts/ci/test_report.py reads the cases that ran
# from the output.
function(tlmhub_add_suite_tests target)
  cmake_parse_arguments(arg "" "" "SUITES;LABELS;PROPERTIES" ${ARGN})
  tlmhub_threads_regex(threads)
  foreach(suite IN LISTS arg_SUITES)
    set(name "${suite}.*")
    add_test(NAME "${name}" COMMAND ${target} "--gtest_filter=${suite}.*")
    set(labels ${arg_LABELS})
    if(name MATCHES "${threads}")
      list(APPEND labels threads)
    endif()
    set_tests_properties("${name}" PROPERTIES LABELS "${labels}" ${arg_PROPERTIES})
  endforeach()
endfunction()
