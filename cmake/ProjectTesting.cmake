# geoflow_add_test(NAME <name> LABEL unit|verification|regression SOURCES <src..> [LIBS <lib..>])
# Builds one GoogleTest executable and registers its tests with CTest under the given label.
find_package(GTest REQUIRED)
include(GoogleTest)

function(geoflow_add_test)
  cmake_parse_arguments(T "" "NAME;LABEL" "SOURCES;LIBS" ${ARGN})
  if(NOT T_LABEL MATCHES "^(unit|verification|regression)$")
    message(FATAL_ERROR "geoflow_add_test(${T_NAME}): LABEL must be unit, verification or regression")
  endif()
  add_executable(${T_NAME} ${T_SOURCES})
  set_target_properties(${T_NAME} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/tests)
  target_link_libraries(${T_NAME} PRIVATE ${T_LIBS} test_support GTest::gtest GTest::gtest_main geoflow_warnings)
  target_compile_definitions(${T_NAME} PRIVATE
    GEOFLOW_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
    GEOFLOW_TEST_DATA_DIR="${PROJECT_SOURCE_DIR}/tests/data"
    GEOFLOW_BIN_DIR="${CMAKE_BINARY_DIR}/bin")
  gtest_discover_tests(${T_NAME}
    PROPERTIES LABELS ${T_LABEL} ENVIRONMENT "${GEOFLOW_SANITIZER_ENVIRONMENT}"
    WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}
    DISCOVERY_TIMEOUT 60)
endfunction()

# geoflow_add_python_test(NAME <name> LABEL <label> SCRIPT <file.py> [TIMEOUT <s>] [ARGS <arg..>])
# Registers a Python test run with Debian's /usr/bin/python3 (numpy, h5py, matplotlib); skipped when
# that interpreter is missing.
find_program(GEOFLOW_PYTHON3 NAMES python3 PATHS /usr/bin NO_DEFAULT_PATH)
function(geoflow_add_python_test)
  cmake_parse_arguments(T "" "NAME;LABEL;SCRIPT;TIMEOUT" "ARGS" ${ARGN})
  if(NOT GEOFLOW_PYTHON3)
    return()
  endif()
  add_test(NAME ${T_NAME} COMMAND ${GEOFLOW_PYTHON3} ${T_SCRIPT} ${T_ARGS})
  set_tests_properties(${T_NAME} PROPERTIES LABELS ${T_LABEL} TIMEOUT ${T_TIMEOUT})
endfunction()
