// Which part of a real grain's spherical harmonics random grains miss: each
// real grain of a folder of SH files (.dat) is measured as it is and as
// "surrogates" that keep its degrees n <= --keep and, above, its own
// amplitude A_n per degree but take a random direction among the degree's
// 2n + 1 real coefficients (set_random_degree, as `grains generate
// --spectrum` draws them); a surrogate with r <= 0 is drawn again. The
// surrogates have exactly the grain's spectrum, so what differs from the real
// grain comes from how its coefficients line up within degrees (its phases),
// not from the amplitudes. Not a test; prints one table.
//
//   build/study_sh_phases FOLDER [--keep 2] [--max-degree -1] [--surrogates 3] [--faces 2000]
#include "bench_args.h"

#include "core/error.h"
#include "geometry/shape_metrics.h"
#include "grains/sh_generator.h"
#include "grains/sh_grain.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

using namespace grainlab;

namespace {

struct Means {
  double r = 0, sph = 0, e = 0, f = 0, c = 0;
  int count = 0;
  void add(const ShapeMetrics& m) {
    r += m.roundness;
    sph += m.sphericity;
    e += m.elongation;
    f += m.flatness;
    c += m.convexity;
    ++count;
  }
  std::string row(const char* name) const {
    return fmt::format("{:<28}{:>8}{:>11.3f}{:>11.3f}{:>11.3f}{:>11.3f}{:>11.3f}", name, count, r / count,
                       sph / count, e / count, f / count, c / count);
  }
};

}  // namespace

int main(int argc, char** argv) {
  bench::check_args(argc, argv, "FOLDER [--keep 2] [--max-degree -1] [--surrogates 3] [--faces 2000]",
                    {"--keep", "--max-degree", "--surrogates", "--faces"}, {}, 2);
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s FOLDER [options]; --help for them\n", argv[0]);
    return 2;
  }
  int keep = 2, max_degree = -1, surrogates = 3, faces = 2000;
  for (int i = 2; i + 1 < argc; i += 2) {
    const std::string a = argv[i];
    const int v = std::atoi(argv[i + 1]);
    if (a == "--keep") keep = v;
    if (a == "--max-degree") max_degree = v;
    if (a == "--surrogates") surrogates = v;
    if (a == "--faces") faces = v;
  }
  try {
    std::vector<std::filesystem::path> files;
    for (const auto& e : std::filesystem::directory_iterator(argv[1])) {
      if (is_sh_file(e.path())) files.push_back(e.path());
    }
    std::sort(files.begin(), files.end());
    Means real, surrogate;
    int refused = 0;
    Rng rng(1);
    for (const auto& file : files) {
      const ShCoefficients c = truncated(read_sh_file(file), max_degree);
      real.add(shape_metrics(sh_mesh(c, faces, file.string())));
      const std::vector<double> a = sh_degree_amplitudes(c);
      for (int k = 0; k < surrogates; ++k) {
        for (;;) {
          ShCoefficients s = c;
          for (int n = keep + 1; n <= s.degree; ++n) set_random_degree(s, n, a[n] * std::abs(c.at(0, 0)), rng);
          try {
            surrogate.add(shape_metrics(sh_mesh(s, faces, "surrogate")));
            break;
          } catch (const InputError&) {
            ++refused;
          }
        }
      }
    }
    fmt::print("{} ({} grains, degrees <= {}, {} kept; {} surrogates refused for r <= 0)\n", argv[1], files.size(),
               max_degree, keep, refused);
    fmt::print("{:<28}{:>8}{:>11}{:>11}{:>11}{:>11}{:>11}\n", "mean", "grains", "roundness", "sphericity",
               "elongation", "flatness", "convexity");
    fmt::print("{}\n{}\n", real.row("real"), surrogate.row("surrogates (own A_n)"));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
  return 0;
}
