# The fuzz harnesses of tests/fuzz: one fuzz_NAME.cpp per reader of outside
# bytes, each defining LLVMFuzzerTestOneInput. With GRAINLAB_FUZZ=ON they are
# libFuzzer binaries (`make fuzz` runs each for a set time); without, each is
# linked with corpus_driver.cpp, a main that feeds it every file of its corpus
# (tests/fuzz/corpus/NAME: seeds and every input that once failed), and that
# corpus run is an ordinary ctest test.
file(GLOB fuzz_srcs CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/tests/fuzz/fuzz_*.cpp)
# What every harness links, compiled once: the input helpers, and without
# libFuzzer the corpus driver's main.
set(fuzz_support_srcs ${CMAKE_SOURCE_DIR}/tests/fuzz/harness_input.cpp)
if(NOT GRAINLAB_FUZZ)
  list(APPEND fuzz_support_srcs ${CMAKE_SOURCE_DIR}/tests/fuzz/corpus_driver.cpp)
endif()
add_library(fuzz_support OBJECT ${fuzz_support_srcs})
target_include_directories(fuzz_support PRIVATE ${CMAKE_SOURCE_DIR}/tests)
target_link_libraries(fuzz_support PRIVATE grainlab_io)
grainlab_precompile(fuzz_support REUSE_FROM grainlab_io)  # a library's: position-independent code
set(fuzz_targets)
foreach(src ${fuzz_srcs})
  get_filename_component(name ${src} NAME_WE)
  string(REGEX REPLACE "^fuzz_" "" corpus ${name})
  add_executable(${name} ${src})
  if(GRAINLAB_FUZZ)
    target_link_options(${name} PRIVATE -fsanitize=fuzzer)
  else()
    add_test(NAME ${name}_corpus COMMAND ${name} ${CMAKE_SOURCE_DIR}/tests/fuzz/corpus/${corpus})
    set_tests_properties(${name}_corpus PROPERTIES LABELS fuzz_corpus ENVIRONMENT "OMP_NUM_THREADS=1")
  endif()
  target_include_directories(${name} PRIVATE ${CMAKE_SOURCE_DIR}/tests)
  target_link_libraries(${name} PRIVATE fuzz_support grainlab_io grainlab_ct)
  grainlab_precompile(${name} REUSE_FROM ${grainlab_exe_pch})  # the benches' (CMakeLists.txt)
  list(APPEND fuzz_targets ${name})
endforeach()
add_custom_target(fuzz_harnesses DEPENDS ${fuzz_targets})
