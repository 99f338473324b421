# mcd_add_pytest_tests(PREFIX FILE ENVIRONMENT LABELS [FIXTURES]): one CTest test
# PREFIX.<name> per top-level `def test_<name>(` of the pytest FILE, run with
# Debian's /usr/bin/python3 in FILE's directory, so CTest's summary counts
# every Python test case. ENVIRONMENT, LABELS and the fixtures each test
# requires (FIXTURES_REQUIRED) are lists; a test whose
# pytest run reports "N skipped in <time>" counts as skipped (not a failure
# whose output quotes mcdtool's "0 skipped" frame summary).
function(mcd_add_pytest_tests prefix pytest_file environment labels)
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${pytest_file})
  get_filename_component(pytest_dir ${pytest_file} DIRECTORY)
  file(STRINGS ${pytest_file} test_lines REGEX "^def test_[a-z0-9_]+\\(")
  foreach(line IN LISTS test_lines)
    string(REGEX REPLACE "^def (test_[a-z0-9_]+)\\(.*" "\\1" test_name "${line}")
    add_test(NAME ${prefix}.${test_name}
             COMMAND /usr/bin/python3 -m pytest -q -p no:cacheprovider
                     --basetemp=${CMAKE_CURRENT_BINARY_DIR}/pytest-${test_name}
                     "${pytest_file}::${test_name}"
             WORKING_DIRECTORY ${pytest_dir})
    set_tests_properties(${prefix}.${test_name} PROPERTIES
                         ENVIRONMENT "${environment}" LABELS "${labels}"
                         SKIP_REGULAR_EXPRESSION "[0-9]+ skipped in [0-9.]+s")
    if(ARGC GREATER 4)
      set_tests_properties(${prefix}.${test_name} PROPERTIES FIXTURES_REQUIRED "${ARGV4}")
    endif()
  endforeach()
endfunction()
