// The command line of a bench, checked before the bench reads it: --help (or
// -h) prints the usage and exits 0; an option the bench does not know, or one
// that needs a value and has none, prints what is wrong and the usage and
// exits 2, rather than running a long bench with the option ignored.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <initializer_list>

namespace grainlab::bench {

// `usage`: the arguments after the program's name, one line. `with_value`:
// options followed by a value; `flags`: options without one. Arguments from
// `first` on are options (those before it are the bench's own positionals).
inline void check_args(int argc, char** argv, const char* usage, std::initializer_list<const char*> with_value,
                       std::initializer_list<const char*> flags = {}, int first = 1) {
  const auto in = [](const char* a, std::initializer_list<const char*> names) {
    for (const char* n : names)
      if (!std::strcmp(a, n)) return true;
    return false;
  };
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--help") || !std::strcmp(argv[i], "-h")) {
      std::printf("usage: %s %s\n", argv[0], usage);
      std::exit(0);
    }
  }
  for (int i = first; i < argc; ++i) {
    const char* arg = argv[i];
    const char* wrong = nullptr;
    if (in(arg, with_value)) {
      if (++i >= argc) wrong = "needs a value";
    } else if (!in(arg, flags)) {
      wrong = "is not an option of this bench";
    }
    if (wrong) {
      std::fprintf(stderr, "%s: '%s' %s\nusage: %s %s\n", argv[0], arg, wrong, argv[0], usage);
      std::exit(2);
    }
  }
}

}  // namespace grainlab::bench
