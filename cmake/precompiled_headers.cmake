# Precompiled headers: most of a translation unit's compile time was reading
# headers, not generating code. Measured on the 2-core AMD EPYC (2026-12-07):
# src/lab/direct_shear_keys.cpp (25 lines) took 6.8 s at -O3, of which 4.4 s
# with -fsyntax-only; <Eigen/Geometry> alone is 2.3 s to parse, gtest 1.5 s,
# nlohmann/json 2.0 s, and the build's 320 translation units took 34 minutes
# of CPU. Now the build's targets read the common headers from four
# precompiled headers (CMakeLists.txt says which) instead of once per file:
# a clean build took 14 min 8 s instead of 17 min 40 s (docs/performance.md).
#
# A precompiled header is the compiler's own state after reading the headers:
# the code generated for a file is the same with or without it, so results
# keep their bits (the golden direct shear checks this). GCC only (the build
# `make test` uses); clang builds (make fuzz, make test-sanitize) go without,
# as they force-include ITK's shim first. GRAINLAB_PCH=OFF turns it off.
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
  option(GRAINLAB_PCH "Precompile the common headers of each target (faster builds, same code)" ON)
else()
  set(GRAINLAB_PCH OFF)
endif()

# Headers every layer's files read (Eigen and fmt come with grainlab_core).
set(grainlab_pch_common
    <Eigen/Core> <Eigen/Geometry> <fmt/format.h>
    <algorithm> <array> <cmath> <cstddef> <cstdint> <cstdio> <cstring> <filesystem> <fstream> <functional>
    <limits> <map> <memory> <numbers> <optional> <span> <sstream> <stdexcept> <string> <string_view>
    <utility> <vector>)

# grainlab_precompile(target HEADERS header...): `target` precompiles the
# common headers and these. grainlab_precompile(target REUSE_FROM owner): it
# reads owner's precompiled header instead of making its own (each is some
# 170 MB and 11 s of CPU; GCC checks that the two targets' options agree and
# otherwise reads the headers as text, with a warning: -Winvalid-pch).
function(grainlab_precompile target)
  if(NOT GRAINLAB_PCH)
    return()
  endif()
  cmake_parse_arguments(arg "" "REUSE_FROM" "HEADERS" ${ARGN})
  if(arg_REUSE_FROM)
    target_precompile_headers(${target} REUSE_FROM ${arg_REUSE_FROM})
  else()
    target_precompile_headers(${target} PRIVATE ${grainlab_pch_common} ${arg_HEADERS})
  endif()
endfunction()
