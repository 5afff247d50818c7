// Force-included into grainlab_ct when clang builds it (the fuzz and
// sanitizer builds). Debian's ITK 5.2 ships an itk_compiler_detection.h
// generated for GCC only: under clang it stops with "Unsupported compiler".
// Clang accepts what GCC 12 does here, so the header is read once with the
// macros of GCC 12 and clang's restored after it; its include guard then
// keeps ITK's own includes of it from running it again.
#pragma once
#pragma clang diagnostic push
#pragma clang diagnostic ignored "-Wbuiltin-macro-redefined"
#pragma push_macro("__clang__")
#pragma push_macro("__GNUC__")
#pragma push_macro("__GNUC_MINOR__")
#undef __clang__
#undef __GNUC__
#undef __GNUC_MINOR__
#define __GNUC__ 12
#define __GNUC_MINOR__ 2
#include <itk_compiler_detection.h>
#pragma pop_macro("__GNUC_MINOR__")
#pragma pop_macro("__GNUC__")
#pragma pop_macro("__clang__")
#pragma clang diagnostic pop
