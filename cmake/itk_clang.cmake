# Clang builds (make fuzz, make test-sanitize): Debian's ITK headers accept
# GCC only; cmake/itk_clang_shim.h lets clang read them. PUBLIC: the tests
# and harnesses that include ct headers read ITK's too.
if(CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  target_compile_options(grainlab_ct PUBLIC -include ${CMAKE_SOURCE_DIR}/cmake/itk_clang_shim.h)
endif()
