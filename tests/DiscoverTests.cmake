# How the GoogleTest executables become ctests, and their labels.
#
# Every test of a suite named in TLMHUB_THREADS_SUITES gets the label `threads` besides its
# own: it starts threads or child processes, and scripts/test.sh runs the label under TSan.
# The Release stage checks the list (scripts/ci/check_threads_label.py).
#
# Every test of a suite named in TLMHUB_LONG_SUITES gets a COST: ctest starts the costly
# tests first, so that on 2 cores a long test does not run alone at the end of a stage
# (a fresh build directory has no timings of earlier runs to order by).
include(GoogleTest)
set(TLMHUB_LONG_TEST_COST 30)

# A regular expression matching the ctest names of the given suites (also
# `Prefix/Suite.Case/N` of parameterised tests and `Suite.*` of whole suites).
function(tlmhub_suites_regex out suites)
  list(JOIN suites "|" alternatives)
  set(${out} "^([A-Za-z0-9_]+/)?(${alternatives})\\." PARENT_SCOPE)
endfunction()

# tlmhub_discover_tests(TARGET SET NAME [FILTER GTEST_FILTER] LABELS LABEL... [PROPERTIES ...])
# One ctest per test case (gtest_discover_tests). gtest_discover_tests writes PROPERTIES out
# unquoted, so a list value ("server;threads") would split into stray property names; the
# labels are set instead by a ctest include file that runs after the discovery, from the
# list of discovered names (named after TARGET and SET, which must be unique per call).
#
# In the sanitizer builds a set without positive FILTER patterns runs one ctest per suite
# instead (`Suite.*`, see tlmhub_add_suite_tests), except the long suites and parameterised
# tests, which keep a ctest per case so that the two cores share them: a sanitized process
# costs its start and its leak check at exit (ASan: 0.4 CPU-seconds for the server tests),
# which one process per case paid some 600 times a stage.
function(tlmhub_discover_tests target)
  cmake_parse_arguments(arg "" "SET;FILTER" "LABELS;PROPERTIES" ${ARGN})
  if(TLMHUB_SANITIZE AND NOT "${arg_FILTER}" MATCHES "^[^-]")
    string(REGEX REPLACE "^-" "" excluded "${arg_FILTER}")
    list(TRANSFORM TLMHUB_LONG_SUITES APPEND ".*" OUTPUT_VARIABLE long_patterns)
    list(APPEND long_patterns "*/*")
    list(JOIN long_patterns ":" per_case)
    set(grouped_excluded "${per_case}")
    if(excluded)
      string(APPEND per_case "-${excluded}")
      string(APPEND grouped_excluded ":${excluded}")
    endif()
    tlmhub_discover_cases(${target} SET ${arg_SET} FILTER "${per_case}" LABELS ${arg_LABELS}
                          PROPERTIES ${arg_PROPERTIES})
    tlmhub_discover_suites(${target} SET ${arg_SET} EXCLUDE "${grouped_excluded}" LABELS ${arg_LABELS}
                           PROPERTIES ${arg_PROPERTIES})
  else()
    tlmhub_discover_cases(${target} ${ARGN})
  endif()
endfunction()

function(tlmhub_discover_cases target)
  cmake_parse_arguments(arg "" "SET;FILTER" "LABELS;PROPERTIES" ${ARGN})
  string(MAKE_C_IDENTIFIER "${target}_${arg_SET}_tests" list)
  set(filter_args "")
  if(arg_FILTER)
    set(filter_args TEST_FILTER "${arg_FILTER}")
  endif()
  gtest_discover_tests(${target} DISCOVERY_TIMEOUT 60 ${filter_args} TEST_LIST ${list}
                       PROPERTIES ${arg_PROPERTIES})
  tlmhub_suites_regex(threads "${TLMHUB_THREADS_SUITES}")
  tlmhub_suites_regex(long "${TLMHUB_LONG_SUITES}")
  set(labels_file "${CMAKE_CURRENT_BINARY_DIR}/${list}_labels.cmake")
  file(WRITE "${labels_file}"
       "foreach(test IN LISTS ${list})\n"
       "  if(test MATCHES [=[${threads}]=])\n"
       "    set_tests_properties(\"\${test}\" PROPERTIES LABELS \"${arg_LABELS};threads\")\n"
       "  else()\n"
       "    set_tests_properties(\"\${test}\" PROPERTIES LABELS \"${arg_LABELS}\")\n"
       "  endif()\n"
       "  if(test MATCHES [=[${long}]=])\n"
       "    set_tests_properties(\"\${test}\" PROPERTIES COST ${TLMHUB_LONG_TEST_COST})\n"
       "  endif()\n"
       "endforeach()\n")
  set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES "${labels_file}")
endfunction()

# One ctest `Suite.*` per suite of TARGET, apart from the tests that match EXCLUDE (a gtest
# filter's patterns): a ctest include file lists the suites when ctest runs, as
# gtest_discover_tests does its cases.
function(tlmhub_discover_suites target)
  cmake_parse_arguments(arg "" "SET;EXCLUDE" "LABELS;PROPERTIES" ${ARGN})
  string(MAKE_C_IDENTIFIER "${target}_${arg_SET}_suites" name)
  tlmhub_suites_regex(threads "${TLMHUB_THREADS_SUITES}")
  set(properties "")
  foreach(value IN LISTS arg_PROPERTIES)
    string(APPEND properties " [==[${value}]==]")
  endforeach()
  file(GENERATE OUTPUT "${CMAKE_CURRENT_BINARY_DIR}/${name}.cmake" CONTENT
"set(executable [==[$<TARGET_FILE:${target}>]==])
execute_process(COMMAND \"\${executable}\" --gtest_list_tests [==[--gtest_filter=*-${arg_EXCLUDE}]==]
                OUTPUT_VARIABLE listing RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  add_test([==[${name}_NOT_LISTED]==] \"\${executable}\" --gtest_list_tests)
  return()
endif()
string(REPLACE \"\\n\" \";\" lines \"\${listing}\")
foreach(line IN LISTS lines)
  if(line MATCHES [==[^([A-Za-z0-9_]+)\\.( .*)?$]==])
    set(test \"\${CMAKE_MATCH_1}.*\")
    add_test(\"\${test}\" \"\${executable}\" \"--gtest_filter=\${test}-${arg_EXCLUDE}\")
    set(labels [==[${arg_LABELS}]==])
    if(test MATCHES [==[${threads}]==])
      list(APPEND labels threads)
    endif()
    set_tests_properties(\"\${test}\" PROPERTIES LABELS \"\${labels}\"
                         WORKING_DIRECTORY [==[${CMAKE_CURRENT_BINARY_DIR}]==]${properties})
  endif()
endforeach()
")
  set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES "${CMAKE_CURRENT_BINARY_DIR}/${name}.cmake")
endfunction()

# tlmhub_add_suite_tests(TARGET SUITES SUITE... LABELS LABEL... [PROPERTIES ...])
# One ctest per suite, named `SUITE.*`, for suites whose tests share what their
# SetUpTestSuite starts (a server, its users): one process runs them all, instead of one
# process per test starting it again. scripts/ci/test_report.py reads the cases that ran
# from the output.
function(tlmhub_add_suite_tests target)
  cmake_parse_arguments(arg "" "" "SUITES;LABELS;PROPERTIES" ${ARGN})
  tlmhub_suites_regex(threads "${TLMHUB_THREADS_SUITES}")
  foreach(suite IN LISTS arg_SUITES)
    set(name "${suite}.*")
    add_test(NAME "${name}" COMMAND ${target} "--gtest_filter=${suite}.*")
    set(labels ${arg_LABELS})
    if(name MATCHES "${threads}")
      list(APPEND labels threads)
    endif()
    # A whole suite is a long test.
    set_tests_properties("${name}" PROPERTIES LABELS "${labels}" COST ${TLMHUB_LONG_TEST_COST} ${arg_PROPERTIES})
  endforeach()
endfunction()
