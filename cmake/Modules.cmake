# Project-wide warning and sanitizer flags, applied to our own targets only.
add_library(hydrodda_flags INTERFACE)
target_compile_options(hydrodda_flags INTERFACE -Wall -Wextra -Wpedantic)
if(HYDRODDA_SANITIZE)
  target_compile_options(hydrodda_flags INTERFACE
    -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
  target_link_options(hydrodda_flags INTERFACE -fsanitize=address,undefined)
endif()

# hydrodda_add_module(NAME DEPENDS <modules or targets>...)
# One static library per module folder src/NAME, built from every .cpp in it, so that a
# module is added to by dropping a file in its folder.
function(hydrodda_add_module name)
  cmake_parse_arguments(ARG "" "" "DEPENDS" ${ARGN})
  file(GLOB sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/${name}/*.cpp)
  set(target hydrodda_${name})
  if(NOT sources)  # a module with headers only so far
    add_library(${target} INTERFACE)
    target_include_directories(${target} INTERFACE ${PROJECT_SOURCE_DIR}/src)
    target_link_libraries(${target} INTERFACE ${ARG_DEPENDS})
    return()
  endif()
  add_library(${target} STATIC ${sources})
  target_include_directories(${target} PUBLIC ${PROJECT_SOURCE_DIR}/src)
  target_link_libraries(${target} PUBLIC ${ARG_DEPENDS} PRIVATE hydrodda_flags)
endfunction()

# hydrodda_add_test_folder(NAME): one GoogleTest executable per tests/NAME folder.
function(hydrodda_add_test_folder name)
  file(GLOB sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/${name}/*.cpp)
  if(NOT sources)
    return()
  endif()
  set(target test_${name})
  add_executable(${target} ${sources})
  target_link_libraries(${target} PRIVATE hydrodda GTest::gtest GTest::gtest_main hydrodda_flags
                        ${ARGN})
  target_compile_definitions(${target} PRIVATE
    HYDRODDA_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
    HYDRODDA_BINARY="$<TARGET_FILE:hydrodda_program>")
  # Each build tree keeps its tests' scratch files apart, so two suites (say `make test` and
  # `make asan`) can run at once without writing into each other's run folders.
  file(MAKE_DIRECTORY ${CMAKE_BINARY_DIR}/test-tmp)
  gtest_discover_tests(${target} DISCOVERY_TIMEOUT 60
                       PROPERTIES LABELS ${name} ENVIRONMENT TMPDIR=${CMAKE_BINARY_DIR}/test-tmp)
endfunction()
