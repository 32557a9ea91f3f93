# Shared build rules for contain's own targets.

# Warnings as errors on the project's own code only.
function(contain_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor
                                           -Wimplicit-fallthrough -Wno-missing-field-initializers
                                           -Werror)
  # GCC 12 reports -Wrestrict false positives inside libstdc++'s std::string operator+ at -O3
  # (GCC bug 105329); the warning says nothing about our code there.
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
    target_compile_options(${target} PRIVATE -Wno-restrict)
  endif()
endfunction()

# contain_library(NAME SOURCES a.cpp b.cpp DEPS contain_values ...)
# A static library contain_<NAME> from src/<NAME>/ with the public headers of include/.
function(contain_library name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS" ${ARGN})
  set(target contain_${name})
  add_library(${target} STATIC ${ARG_SOURCES})
  target_include_directories(${target}
    PUBLIC $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/include> $<INSTALL_INTERFACE:include>
    PRIVATE ${PROJECT_SOURCE_DIR}/src)
  target_compile_features(${target} PUBLIC cxx_std_20)
  target_link_libraries(${target} PUBLIC ${ARG_DEPS})
  set_target_properties(${target} PROPERTIES POSITION_INDEPENDENT_CODE ON)
  contain_warnings(${target})
  contain_sanitized_library(${target})
  # Unity files of a few sources each: the standard and the library's own headers are most of a
  # source's compile time, parsed once a batch. File-local names must differ across the sources
  # of one library (or the source is listed with SKIP_UNITY_BUILD_INCLUSION).
  set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE 8)
endfunction()

# The library's code under the sanitizers at -O1 (what AddressSanitizer's documentation advises
# for speed): the suite's time goes into the library, and at -O0 the sanitizer build's tests took
# 437 s of the CI's 22 minutes. The tests, the CLI and the fuzz drivers stay at -O0, which builds
# faster; the checks are the same at either level.
function(contain_sanitized_library target)
  if(CONTAIN_SANITIZE)
    target_compile_options(${target} PRIVATE $<$<CONFIG:Debug>:-O1>)
    # clang spends most of an unoptimised compile parsing the standard headers: precompiled here
    # only, so that the optimised build still proves every source includes what it uses.
    target_precompile_headers(${target} PRIVATE
      <algorithm> <array> <cmath> <cstdint> <limits> <optional> <span> <string> <utility> <vector>)
  endif()
endfunction()

# The flags every test executable compiles with (contain_test below, and the owner of the
# shared precompiled header).
function(contain_test_flags target)
  target_link_libraries(${target} PRIVATE contain_test_support GTest::gtest_main)
  target_include_directories(${target} PRIVATE ${PROJECT_SOURCE_DIR}/src ${PROJECT_SOURCE_DIR}/tests)
  target_compile_definitions(${target} PRIVATE
    CONTAIN_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
    CONTAIN_SHARED_DIR="${PROJECT_SOURCE_DIR}/../shared")
  contain_warnings(${target})
  # Test code at -O1 in optimised builds: the library under test keeps the build's level, and the
  # tests' own code (drivers, GMP oracles) compiles a third faster than at -O3.
  target_compile_options(${target} PRIVATE $<$<NOT:$<CONFIG:Debug>>:-O1> -Winvalid-pch)
endfunction()

# contain_test(NAME SOURCES a_test.cpp ... LIBS contain_inside ...)
# One GoogleTest executable contain_<NAME>_tests, its tests registered with CTest one by one.
function(contain_test name)
  cmake_parse_arguments(ARG "" "" "SOURCES;LIBS" ${ARGN})
  set(target contain_${name}_tests)
  add_executable(${target} ${ARG_SOURCES})
  target_link_libraries(${target} PRIVATE ${ARG_LIBS})
  contain_test_flags(${target})
  # Parsing GoogleTest and the standard headers is over half of a test file's compile time: one
  # precompiled header (external headers only, so that editing the library's headers does not
  # rebuild it), built once and shared by every test binary (one a binary cost 9 s of CPU each,
  # 13% of the optimised build).
  if(NOT TARGET contain_test_headers)
    set(anchor ${PROJECT_BINARY_DIR}/tests/contain_test_headers.cpp)
    file(CONFIGURE OUTPUT ${anchor} CONTENT "// The owner of the tests' precompiled header.\n")
    add_library(contain_test_headers OBJECT ${anchor})
    contain_test_flags(contain_test_headers)
    target_precompile_headers(contain_test_headers PRIVATE
      <gtest/gtest.h> <gmpxx.h> <algorithm> <array> <cmath> <cstdint> <filesystem> <fstream>
      <functional> <limits> <map> <optional> <random> <span> <sstream> <string> <vector>)
  endif()
  target_precompile_headers(${target} REUSE_FROM contain_test_headers)
  # Built as unity files of a few sources each: a test file's own code is small beside the
  # headers of GoogleTest and the library it includes, parsed once a batch instead of once a file.
  # File-local names must differ between the sources of one test binary (or the source is
  # listed with SKIP_UNITY_BUILD_INCLUSION).
  set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE 8)
  gtest_discover_tests(${target} DISCOVERY_TIMEOUT 60 PROPERTIES LABELS ${name})
endfunction()
