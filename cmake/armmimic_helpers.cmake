# armmimic_add_layer(NAME <target> DIR <src dir> DEPS <targets...>)
# A layer is a static library built from every .cpp in its folder; its public headers live in
# include/armmimic/<layer>/. Sources are globbed so that adding a file needs no edit here.
function(armmimic_add_layer)
  cmake_parse_arguments(L "" "NAME" "DEPS" ${ARGN})
  file(GLOB _srcs CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*.cpp)
  file(GLOB _hdrs CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*.h)
  if(NOT _srcs)
    # A layer whose sources have not landed yet: headers only.
    add_library(${L_NAME} INTERFACE)
    target_include_directories(${L_NAME} INTERFACE ${PROJECT_SOURCE_DIR}/include ${CMAKE_BINARY_DIR}/generated)
    target_link_libraries(${L_NAME} INTERFACE ${L_DEPS})
    return()
  endif()
  add_library(${L_NAME} STATIC ${_srcs} ${_hdrs})
  target_include_directories(${L_NAME}
    PUBLIC ${PROJECT_SOURCE_DIR}/include ${CMAKE_BINARY_DIR}/generated
    PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
  target_link_libraries(${L_NAME} PUBLIC ${L_DEPS})
endfunction()

# armmimic_add_sources(<target>)
# Adds every .cpp and .h of the calling folder to <target> (a layer split into folders).
function(armmimic_add_sources target)
  file(GLOB _srcs CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*.cpp ${CMAKE_CURRENT_SOURCE_DIR}/*.h)
  target_sources(${target} PRIVATE ${_srcs})
endfunction()

# armmimic_add_test_suite(NAME <exe> DEPS <targets...>)
# One GoogleTest binary per layer (a relink of Qt per test file would not fit a 2-core machine).
# With SUBDIRS, the .cpp files of those subfolders are added too (a layer whose tests are split
# into folders, like the engines').
function(armmimic_add_test_suite)
  cmake_parse_arguments(T "" "NAME" "DEPS;SUBDIRS" ${ARGN})
  file(GLOB _srcs CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*.cpp)
  foreach(_dir ${T_SUBDIRS})
    file(GLOB _sub CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/${_dir}/*.cpp)
    list(APPEND _srcs ${_sub})
  endforeach()
  add_executable(${T_NAME} ${_srcs} ${PROJECT_SOURCE_DIR}/tests/common/test_main.cpp
    ${PROJECT_SOURCE_DIR}/tests/common/test_util.cpp)
  target_include_directories(${T_NAME} PRIVATE ${PROJECT_SOURCE_DIR}/tests/common)
  # The suites make and check videos and images with OpenCV's own codecs.
  target_link_libraries(${T_NAME} PRIVATE ${T_DEPS} opencv_imgcodecs opencv_videoio GTest::gtest)
  target_compile_definitions(${T_NAME} PRIVATE
    ARMMIMIC_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
    ARMMIMIC_CLI_PATH="$<TARGET_FILE:armmimic-cli>")
  add_dependencies(${T_NAME} armmimic-cli)
  set(_env "QT_QPA_PLATFORM=offscreen;LC_ALL=C.UTF-8")
  if(ARMMIMIC_TEST_PER_SUITE)
    # One ctest test per GoogleTest suite (cmake/gtest_suites.cmake), listed after each link.
    set(_ctest_file "${CMAKE_CURRENT_BINARY_DIR}/${T_NAME}_suites.cmake")
    string(REPLACE ";" "|" _env_arg "${_env}")
    add_custom_command(TARGET ${T_NAME} POST_BUILD
      COMMAND ${CMAKE_COMMAND} -D TEST_EXECUTABLE=$<TARGET_FILE:${T_NAME}>
        -D CTEST_FILE=${_ctest_file} -D WORKING_DIR=${CMAKE_CURRENT_BINARY_DIR}
        "-D TEST_ENV=${_env_arg}" -P ${PROJECT_SOURCE_DIR}/cmake/gtest_suites.cmake
      VERBATIM)
    set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES ${_ctest_file})
  else()
    gtest_discover_tests(${T_NAME} DISCOVERY_TIMEOUT 60 PROPERTIES ENVIRONMENT "${_env}")
  endif()
endfunction()
