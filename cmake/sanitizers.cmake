# Instrumented builds, each in a build folder of its own (see the Makefile):
#   GRAINLAB_SANITIZE=ON  AddressSanitizer + UndefinedBehaviorSanitizer on
#                         every target (`make test-sanitize`, build-sanitize/).
#   GRAINLAB_FUZZ=ON      clang only: the libraries instrumented for libFuzzer
#                         (and ASan + UBSan), and the harnesses of tests/fuzz
#                         linked with -fsanitize=fuzzer (`make fuzz`, build-fuzz/).
# Included before the layers are defined, so that every target gets the flags.
option(GRAINLAB_SANITIZE "Build with AddressSanitizer and UndefinedBehaviorSanitizer" OFF)
option(GRAINLAB_FUZZ "Build the libFuzzer harnesses of tests/fuzz (needs clang)" OFF)

set(grainlab_sanitizers -fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer)
if(GRAINLAB_SANITIZE OR GRAINLAB_FUZZ)
  add_compile_options(${grainlab_sanitizers} -g)
  add_link_options(-fsanitize=address,undefined)
endif()
if(GRAINLAB_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "GRAINLAB_FUZZ=ON needs clang (libFuzzer): configure with -DCMAKE_CXX_COMPILER=clang++-14 "
                        "-DCMAKE_C_COMPILER=clang-14, or use `make fuzz`")
  endif()
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()

# ITK's header code compiled into the files that include it is not checked
# (cmake/sanitizer_ignorelist.txt says why); every line of grainlab's still is.
# The files: itk_including_srcs, set by CMakeLists.txt.
if((GRAINLAB_SANITIZE OR GRAINLAB_FUZZ) AND CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  set_source_files_properties(${itk_including_srcs} PROPERTIES COMPILE_OPTIONS
                              "-fsanitize-ignorelist=${CMAKE_SOURCE_DIR}/cmake/sanitizer_ignorelist.txt")
endif()
