# The Python client (clients/python) and docs/scripting.md, tested against a real
# tlmhub-server (label `python`). `python/venvs` builds two venvs in the build tree with
# Debian's Python, offline: `system` (--system-site-packages: Debian's NumPy,
# websocket-client and pandas) and `isolated` (none of them). Then every test module of
# clients/python/tests runs in each venv as its own ctest, told what the venv must have, and
# the scripting guide's examples run in order in the system venv.
if(TARGET tlmhub-server)
  set(TLMHUB_DEBIAN_PYTHON /usr/bin/python3 CACHE FILEPATH
      "Debian's Python 3.11 for the Python client's venvs (python3-venv, python3-numpy, python3-websocket, python3-pandas)")
  set(TLMHUB_PYTHON_CLIENT ${PROJECT_SOURCE_DIR}/clients/python)
  set(TLMHUB_PYTHON_VENVS ${CMAKE_CURRENT_BINARY_DIR}/python-venvs)
  set(TLMHUB_PYTHON_TEST_ENV
      "TLMHUB_SERVER_BIN=$<TARGET_FILE:tlmhub-server>"
      "TLMHUB_SHARED_DIR=${TLMHUB_SHARED_DIR}"
      "PYTHONDONTWRITEBYTECODE=1")

  add_test(NAME python/venvs
           COMMAND ${TLMHUB_DEBIAN_PYTHON} ${TLMHUB_PYTHON_CLIENT}/tests/make_venvs.py
                   --python ${TLMHUB_DEBIAN_PYTHON} ${TLMHUB_PYTHON_VENVS})
  set_tests_properties(python/venvs PROPERTIES LABELS "python" TIMEOUT 300
                       FIXTURES_SETUP tlmhub-python-venvs)

  # Run from the tests directory: `import tlmhub` then finds the venv's installed package,
  # not the source tree.
  file(GLOB TLMHUB_PYTHON_TESTS CONFIGURE_DEPENDS ${TLMHUB_PYTHON_CLIENT}/tests/test_*.py)
  foreach(venv IN ITEMS system isolated)
    if(venv STREQUAL "system")
      set(has 1)
    else()
      set(has 0)
    endif()
    foreach(file IN LISTS TLMHUB_PYTHON_TESTS)
      get_filename_component(module "${file}" NAME_WE)
      add_test(NAME python/${venv}/${module}
               COMMAND ${TLMHUB_PYTHON_VENVS}/${venv}/bin/python -m unittest -v ${module}
               WORKING_DIRECTORY ${TLMHUB_PYTHON_CLIENT}/tests)
      set_tests_properties(python/${venv}/${module} PROPERTIES LABELS "python" TIMEOUT 180
        FIXTURES_REQUIRED tlmhub-python-venvs
        ENVIRONMENT "${TLMHUB_PYTHON_TEST_ENV};TLMHUB_EXPECT_NUMPY=${has};TLMHUB_EXPECT_WEBSOCKET=${has};TLMHUB_EXPECT_PANDAS=${has};TLMHUB_HANG_REPORT_SECONDS=165")
    endforeach()
  endforeach()

  add_test(NAME python/docs/scripting
           COMMAND ${TLMHUB_PYTHON_VENVS}/system/bin/python
                   ${CMAKE_CURRENT_SOURCE_DIR}/docs/test_scripting_docs.py
                   ${PROJECT_SOURCE_DIR}/docs/scripting.md)
  set_tests_properties(python/docs/scripting PROPERTIES LABELS "python" TIMEOUT 300 COST ${TLMHUB_LONG_TEST_COST}
    FIXTURES_REQUIRED tlmhub-python-venvs
    ENVIRONMENT "${TLMHUB_PYTHON_TEST_ENV};TLMHUB_CLI_BIN=$<TARGET_FILE:tlmhub-cli>")
endif()
