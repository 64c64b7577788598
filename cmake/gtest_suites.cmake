# Run after a test binary is linked (cmake -P), when ARMMIMIC_TEST_PER_SUITE is on: lists the
# binary's GoogleTest suites and writes CTEST_FILE, which registers one ctest test per suite,
# named <layer>/<suite> (robot_tests' FuzzRegression is robot/FuzzRegression: two binaries may
# hold suites of one name) and run as `<binary> --gtest_filter=<suite>.*`. The sanitizer build
# uses it: every test process there pays the sanitizer's start and its leak check at exit, once
# per suite instead of once per test. As gtest_discover_tests does, a skipped test marks its
# ctest test (here the whole suite) skipped, which scripts/run-ctest.sh counts as a failure.
#   -D TEST_EXECUTABLE=<binary> -D CTEST_FILE=<file> -D WORKING_DIR=<dir> -D TEST_ENV=<a=b|c=d>
execute_process(
  COMMAND "${TEST_EXECUTABLE}" --gtest_list_tests
  WORKING_DIRECTORY "${WORKING_DIR}"
  OUTPUT_VARIABLE _listing
  RESULT_VARIABLE _rc
  TIMEOUT 60)
if(NOT _rc EQUAL 0)
  message(FATAL_ERROR
    "gtest_suites: ${TEST_EXECUTABLE} --gtest_list_tests failed (${_rc}):\n${_listing}")
endif()

string(REPLACE "|" ";" TEST_ENV "${TEST_ENV}")
get_filename_component(_layer "${TEST_EXECUTABLE}" NAME)
string(REGEX REPLACE "_tests$" "" _layer "${_layer}")
string(REPLACE "\n" ";" _lines "${_listing}")
set(_out "")
set(_count 0)
foreach(_line IN LISTS _lines)
  # Suite lines start in the first column ("Suite." or "Prefix/Suite.  # TypeParam = ...");
  # the test lines under them are indented.
  if(_line MATCHES "^([^ #]+)\\.")
    set(_suite "${CMAKE_MATCH_1}")
    set(_name "${_layer}/${_suite}")
    string(APPEND _out
      "add_test([==[${_name}]==] [==[${TEST_EXECUTABLE}]==] [==[--gtest_filter=${_suite}.*]==])\n"
      "set_tests_properties([==[${_name}]==] PROPERTIES WORKING_DIRECTORY [==[${WORKING_DIR}]==]"
      " ENVIRONMENT [==[${TEST_ENV}]==] SKIP_REGULAR_EXPRESSION [==[\\[  SKIPPED \\]]==])\n")
    math(EXPR _count "${_count} + 1")
  endif()
endforeach()
if(_count EQUAL 0)
  message(FATAL_ERROR "gtest_suites: ${TEST_EXECUTABLE} lists no test suite")
endif()
file(WRITE "${CTEST_FILE}" "${_out}")
