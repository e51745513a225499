# tlmhub_threads_only_sources(VAR): in a TSan build, keeps of the test sources in list VAR only
# the files that hold a test of a suite named in TLMHUB_THREADS_SUITES, and the files that hold
# no test at all (harness code). scripts/test.sh runs nothing but the label `threads` under
# TSan, so compiling the other test files there, instrumented, was work for nothing. Outside
# TSan builds VAR is left as it is.
#
# A file is read for its `TEST(Suite, `, `TEST_F(Suite, ` and `TEST_P(Suite, ` lines; each file
# read becomes a configure dependency, so a threads test added to a file that was left out
# brings it back on the next build.
function(tlmhub_threads_only_sources var)
  if(NOT TLMHUB_SANITIZE MATCHES "thread")
    return()
  endif()
  set(kept)
  foreach(source IN LISTS ${var})
    set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${source}")
    file(STRINGS "${source}" test_lines REGEX "^TEST(_F|_P)?\\(")
    set(keep TRUE)
    if(test_lines)
      set(keep FALSE)
      foreach(line IN LISTS test_lines)
        string(REGEX REPLACE "^TEST(_F|_P)?\\( *([A-Za-z0-9_]+).*" "\\2" suite "${line}")
        if(suite IN_LIST TLMHUB_THREADS_SUITES)
          set(keep TRUE)
          break()
        endif()
      endforeach()
    endif()
    if(keep)
      list(APPEND kept "${source}")
    endif()
  endforeach()
  set(${var} ${kept} PARENT_SCOPE)
endfunction()
