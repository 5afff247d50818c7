# The fuzz harnesses of tests/fuzz: one fuzz_NAME.cpp per reader of outside
# bytes, each defining LLVMFuzzerTestOneInput. With GRAINLAB_FUZZ=ON they are
# libFuzzer binaries (`make fuzz` runs each for a set time); without, each is
# linked with corpus_driver.cpp, a main that feeds it every file of its corpus
# (tests/fuzz/corpus/NAME: seeds and every input that once failed), and that
# corpus run is an ordinary ctest test.
file(GLOB fuzz_srcs CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/tests/fuzz/fuzz_*.cpp)
set(fuzz_targets)
foreach(src ${fuzz_srcs})
  get_filename_component(name ${src} NAME_WE)
  string(REGEX REPLACE "^fuzz_" "" corpus ${name})
  if(GRAINLAB_FUZZ)
    add_executable(${name} ${src} ${CMAKE_SOURCE_DIR}/tests/fuzz/harness_input.cpp)
    target_link_options(${name} PRIVATE -fsanitize=fuzzer)
  else()
    add_executable(${name} ${src} ${CMAKE_SOURCE_DIR}/tests/fuzz/harness_input.cpp
                   ${CMAKE_SOURCE_DIR}/tests/fuzz/corpus_driver.cpp)
    add_test(NAME ${name}_corpus COMMAND ${name} ${CMAKE_SOURCE_DIR}/tests/fuzz/corpus/${corpus})
    set_tests_properties(${name}_corpus PROPERTIES LABELS fuzz_corpus ENVIRONMENT "OMP_NUM_THREADS=1")
  endif()
  target_include_directories(${name} PRIVATE ${CMAKE_SOURCE_DIR}/tests)
  target_link_libraries(${name} PRIVATE grainlab_io grainlab_ct)
  list(APPEND fuzz_targets ${name})
endforeach()
add_custom_target(fuzz_harnesses DEPENDS ${fuzz_targets})
