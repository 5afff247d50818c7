// `grainlab grains import | fit-sh | spectrum`: grains described by spherical
// harmonics (sh_grain.h): meshed from coefficient files, fitted to meshes,
// and a sand's spectrum and shape statistics.
#include "apps/commands.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/timer.h"
#include "geometry/mesh_check.h"
#include "geometry/mesh_io.h"
#include "geometry/shape_metrics.h"
#include "grains/grain_set.h"
#include "grains/sh_fit.h"
#include "grains/sh_generator.h"
#include "grains/sh_grain.h"
#include "grains/sh_shape_model.h"
#include "io/sh_spectrum_file.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace grainlab::apps {

namespace {

namespace fs = std::filesystem;

struct ImportOptions {
  std::vector<std::string> inputs;
  std::string out;
  int faces = 2000;
  ShOptions sh;
};

struct FitOptions {
  std::string mesh;
  int degree = 30;
  std::string out;
  double unit = 1e-3;
};

struct SpectrumOptions {
  std::vector<std::string> inputs;
  std::string out;
  int faces = 2000;
  ShOptions sh;
  int degree = 30;
  int model_degree = kDefaultModelDegree;
  int components = kDefaultModelComponents;
};

// The files named, folders expanded to the files in them that `keep` accepts (sorted).
template <typename Keep>
std::vector<fs::path> expand(const std::vector<std::string>& inputs, Keep keep, const char* what) {
  std::vector<fs::path> files;
  for (const std::string& in : inputs) {
    const fs::path p(in);
    if (fs::is_directory(p)) {
      std::vector<fs::path> found;
      for (const auto& e : fs::directory_iterator(p)) {
        if (e.is_regular_file() && keep(e.path())) found.push_back(e.path());
      }
      if (found.empty()) input_error("folder '{}' holds no {}", in, what);
      std::sort(found.begin(), found.end());
      files.insert(files.end(), found.begin(), found.end());
    } else if (fs::is_regular_file(p)) {
      if (!keep(p)) input_error("'{}' is not {}", in, what);
      files.push_back(p);
    } else {
      input_error("'{}' is neither a file nor a folder", in);
    }
  }
  return files;
}

int run_import(const ImportOptions& o) {
  const std::vector<fs::path> files = expand(o.inputs, is_sh_file, "spherical-harmonic file (.dat)");
  // Read and mesh every file first: a bad one stops the command before anything is written.
  Stopwatch clock;
  std::vector<TriMesh> meshes;
  for (const fs::path& f : files) meshes.push_back(load_sh_grain(f, o.faces, o.sh));
  const double seconds = clock.seconds();
  std::error_code ec;
  fs::create_directories(o.out, ec);
  if (ec) input_error("cannot create output folder '{}': {}", o.out, ec.message());
  for (std::size_t i = 0; i < files.size(); ++i) {
    write_stl(meshes[i], fs::path(o.out) / (files[i].stem().string() + ".stl"));
  }
  fmt::print("wrote {} grains ({} faces each, metres, about each file's origin) to {}; read and meshed in {:.3f} s "
             "({:.1f} ms a grain)\n  measure them with `grainlab grains stats {}`\n",
             files.size(), o.faces, o.out, seconds, 1e3 * seconds / files.size(), o.out);
  return 0;
}

int run_fit(const FitOptions& o) {
  const TriMesh mesh = load_mesh(o.mesh);
  Stopwatch clock;
  ShFit fit = fit_sh(mesh, o.degree, o.mesh);
  const double seconds = clock.seconds();
  const std::string out = o.out.empty() ? fs::path(o.mesh).replace_extension(kShExtension).string() : o.out;
  for (auto& a : fit.coefficients.a) a /= o.unit;
  write_sh_file(fit.coefficients, out);
  fmt::print("fitted degree {} to {} ({} rays from its centroid ({:.6g}, {:.6g}, {:.6g}) m) in {:.2f} s\n"
             "  RMS radial error {:.4g} m = {:.3f} % of d_eq ({:.6g} m); largest {:.3f} % of d_eq\n"
             "  wrote {} (r in units of {} m; the file's origin is the centroid)\n",
             o.degree, o.mesh, fit.directions, fit.centre.x(), fit.centre.y(), fit.centre.z(), seconds,
             fit.rms_error, 100 * fit.rms_error / fit.equivalent_diameter, fit.equivalent_diameter,
             100 * fit.max_error / fit.equivalent_diameter, out, o.unit);
  return 0;
}

// Mean, sample standard deviation, minimum and maximum.
struct Stats {
  double mean = 0, std = 0, min = 0, max = 0;
};

Stats stats_of(const std::vector<double>& v) {
  Stats s{0, 0, *std::min_element(v.begin(), v.end()), *std::max_element(v.begin(), v.end())};
  for (double x : v) s.mean += x / v.size();
  for (double x : v) s.std += (x - s.mean) * (x - s.mean);
  s.std = v.size() > 1 ? std::sqrt(s.std / (v.size() - 1)) : 0;
  return s;
}

std::string toml_stats(const char* key, const std::vector<double>& v, const char* comment) {
  const Stats s = stats_of(v);
  return fmt::format("{} = {{ mean = {:.6g}, std = {:.6g}, min = {:.6g}, max = {:.6g} }}  # {}\n", key, s.mean, s.std,
                     s.min, s.max, comment);
}

std::string toml_array(const std::vector<double>& v) {
  std::string s = "[";
  for (std::size_t i = 0; i < v.size(); ++i) s += fmt::format("{}{:.6g}", i ? ", " : "", v[i]);
  return s + "]";
}

int run_spectrum(const SpectrumOptions& o) {
  const std::vector<fs::path> files = expand(o.inputs, is_grain_file, "grain file (.dat, .stl, .obj, .ply)");
  std::vector<std::vector<double>> amplitudes;
  std::vector<ShCoefficients> grains;
  std::vector<double> d, r, sph, e, f, c;
  int degree = 1000;
  for (const fs::path& file : files) {
    const bool sh = is_sh_file(file);
    const TriMesh mesh = load_grain_file(file, o.faces, o.sh);
    const ShCoefficients coefficients =
        sh ? truncated(read_sh_file(file), o.sh.max_degree) : fit_sh(mesh, o.degree, file.string()).coefficients;
    amplitudes.push_back(sh_degree_amplitudes(coefficients));
    grains.push_back(coefficients);
    degree = std::min(degree, coefficients.degree);
    const ShapeMetrics s = shape_metrics(mesh);
    d.push_back(s.equivalent_diameter);
    r.push_back(s.roundness);
    sph.push_back(s.sphericity);
    e.push_back(s.elongation);
    f.push_back(s.flatness);
    c.push_back(s.convexity);
  }
  std::vector<double> mean(degree + 1), spread(degree + 1);
  for (int n = 0; n <= degree; ++n) {
    std::vector<double> a;
    for (const auto& amp : amplitudes) a.push_back(amp[n]);
    const Stats s = stats_of(a);
    mean[n] = s.mean;
    spread[n] = s.std;
  }
  std::string text = fmt::format(
      "# A sand's shape: `grainlab grains spectrum` of {} grains ({} faces each for the metrics).\n"
      "[set]\ngrains = {}\ndegree = {}\nunit_m = {}  # metres per unit of the SH files\n\n"
      "[spectrum]\n"
      "# A_n / A_0, n = 0..degree: A_n = sqrt(sum_m |a_nm|^2), the rotation-invariant amplitude of degree n\n"
      "mean = {}\nstd = {}\n\n[shape]\n",
      files.size(), o.faces, files.size(), degree, o.sh.unit, toml_array(mean), toml_array(spread));
  text += toml_stats("equivalent_diameter_m", d, "(6 V / pi)^(1/3), m");
  text += toml_stats("roundness", r, "Wadell, mean of the three principal projections");
  text += toml_stats("sphericity", sph, "area of the equal-volume sphere / surface area");
  text += toml_stats("elongation", e, "I / L");
  text += toml_stats("flatness", f, "S / I");
  text += toml_stats("convexity", c, "volume / convex hull volume");
  ShShapeModel model;
  if (o.model_degree >= 0 && grains.size() >= 2) {
    model = fit_sh_shape_model(grains, std::min(o.model_degree, degree), o.components, o.faces);
    text += sh_model_toml(model);
  }
  write_file_atomically(o.out, text);
  auto at = [&](int n) { return n <= degree ? fmt::format("{:.4f}", mean[n]) : std::string("-"); };
  const Stats sd = stats_of(d), sr = stats_of(r);
  fmt::print("wrote {}: {} grains, d_eq {:.4g} m ({:.4g}-{:.4g}), roundness {:.3f} +- {:.3f}, sphericity {:.3f}, "
             "elongation {:.3f}, flatness {:.3f}, convexity {:.3f}\n"
             "  A_n/A_0 at n = 2, 5, 10, 20: {}, {}, {}, {}\n",
             o.out, files.size(), sd.mean, sd.min, sd.max, sr.mean, sr.std, stats_of(sph).mean, stats_of(e).mean,
             stats_of(f).mean, stats_of(c).mean, at(2), at(5), at(10), at(20));
  if (!model.empty()) {
    double held = 0;
    for (const ShCoefficients& g : grains) {
      const std::vector<double> x = sh_real_vector(sh_aligned(truncated(g, model.degree), o.faces), model.degree);
      std::vector<double> xn(x.size());
      for (std::size_t j = 0; j < x.size(); ++j) xn[j] = x[j] / x[0];
      held += (1 - unexplained_fraction(model, xn)) / grains.size();
    }
    fmt::print("  shape model: degrees <= {}, {} components of {} grains; the model's span holds {:.0f} % of a "
               "grain's deviation from the mean shape (mean over the grains)\n",
               model.degree, model.components.size(), grains.size(), 100 * held);
  }
  return 0;
}

}  // namespace

int run_generate_from_spectrum(const std::string& spectrum_file, const std::string& method_name, int count,
                               std::uint64_t seed, const std::string& out, int faces) {
  const ShSpectrumFile file = read_sh_spectrum(spectrum_file);
  const ShSpectrum& spectrum = file.spectrum;
  const ShMethod method = !method_name.empty()       ? parse_sh_method(method_name)
                          : spectrum.model.empty() ? ShMethod::random_phase
                                                   : ShMethod::shape_model;
  Stopwatch clock;
  const ShGrains grains = generate_sh_grains(spectrum, count, seed, faces, method);
  const double seconds = clock.seconds();
  std::error_code ec;
  fs::create_directories(out, ec);
  if (ec) input_error("cannot create output folder '{}': {}", out, ec.message());
  std::vector<double> d;
  std::vector<std::vector<double>> shape(std::size(kSpectrumShapeKeys));
  for (std::size_t i = 0; i < grains.meshes.size(); ++i) {
    write_stl(grains.meshes[i], fs::path(out) / fmt::format("sh-{:04d}.stl", i + 1));
    const ShapeMetrics s = shape_metrics(grains.meshes[i]);
    d.push_back(s.equivalent_diameter);
    const double values[] = {s.roundness, s.sphericity, s.elongation, s.flatness, s.convexity};
    for (std::size_t k = 0; k < shape.size(); ++k) shape[k].push_back(values[k]);
  }
  fmt::print("wrote {} grains of degree {} drawn from {} by the {} method ({} faces each, metres, centred, principal "
             "frame) to {} in {:.2f} s; {} draws refused for r <= 0\n",
             count, spectrum.degree(), spectrum_file, sh_method_name(method), faces, out, seconds, grains.rejected);
  const Stats sd = stats_of(d);
  fmt::print("  {:<22}{:>22}{:>22}\n", "mean (std)", "generated", "spectrum's set");
  fmt::print("  {:<22}{:>22}{:>22}\n", "d_eq (m)", fmt::format("{:.4g} ({:.3g})", sd.mean, sd.std),
             fmt::format("{:.4g} ({:.3g})", spectrum.d_eq_mean, spectrum.d_eq_std));
  for (std::size_t k = 0; k < shape.size(); ++k) {
    const Stats s = stats_of(shape[k]);
    std::string real = "-";
    for (const auto& [key, mean] : file.shape_means) {
      if (key == kSpectrumShapeKeys[k]) real = fmt::format("{:.3f}", mean);
    }
    fmt::print("  {:<22}{:>22}{:>22}\n", kSpectrumShapeKeys[k], fmt::format("{:.3f} ({:.3f})", s.mean, s.std), real);
  }
  for (int n : {2, 3, 5, 10, 20}) {
    if (n > spectrum.degree()) break;
    std::vector<double> a;
    for (const ShCoefficients& c : grains.coefficients) a.push_back(sh_degree_amplitudes(c)[n]);
    const Stats s = stats_of(a);
    fmt::print("  {:<22}{:>22}{:>22}\n", fmt::format("A_{}/A_0", n), fmt::format("{:.4f} ({:.4f})", s.mean, s.std),
               fmt::format("{:.4f} ({:.4f})", spectrum.mean[n], spectrum.std[n]));
  }
  return 0;
}

void add_sh_file_options(CLI::App& cmd, int& faces, ShOptions& sh) {
  cmd.add_option("--faces", faces, "triangles of the mesh of each SH file (.dat)")
      ->check(CLI::Range(8, 1000000))
      ->capture_default_str();
  cmd.add_option("--unit", sh.unit,
                 "metres per unit of the SH files (they do not say): 1e-3 for millimetres (VCCTL's LS-coarse and "
                 "MA113AB-2-fine sets), 1e-6 for micrometres")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd.add_option("--max-degree", sh.max_degree,
                 "keep only the degrees n <= this of the SH files (a smoother grain); -1: all of them")
      ->check(CLI::Range(-1, 200))
      ->capture_default_str();
}

Command add_grains_sh_commands(CLI::App& grains) {
  auto im = std::make_shared<ImportOptions>();
  auto* import = grains.add_subcommand(
      "import",
      "mesh grains described by spherical harmonics (SH) and write them as binary STL files (metres).\n"
      "An SH file (.dat, e.g. NIST VCCTL's CT-scanned particles after Garboczi 2002) gives a star-shaped\n"
      "surface r(theta, phi) = Re sum_{n<=N} sum_{|m|<=n} a_nm Y_nm(theta, phi) about its origin, one line\n"
      "`n m Re(a_nm) Im(a_nm)` per coefficient (every |m| <= n, n = 0..N, once; no header). The surface is\n"
      "evaluated at --faces/2 + 2 evenly spread directions and triangulated (exactly --faces triangles);\n"
      "each vertex is moved out by 3/4 of its triangles' sag, so that volume and area are unbiased (a sphere\n"
      "at 2000 faces within 0.1 %). A file with a bad line (not four numbers, |m| > n, NaN), a coefficient\n"
      "given twice or missing (truncated), or r <= 0 in some direction is refused with the file, line or\n"
      "direction; then nothing is written. A run reads .dat files in its [grains] folder the same way.");
  import->add_option("files", im->inputs, "SH files (.dat), or folders of them")->required();
  import->add_option("--out", im->out, "output folder (created if missing); one <name>.stl per file")->required();
  add_sh_file_options(*import, im->faces, im->sh);
  import->add_option("--d-eq", im->sh.d_eq, "scale every grain to this volume-equivalent diameter (m) instead of --unit")
      ->check(CLI::PositiveNumber);

  auto fo = std::make_shared<FitOptions>();
  auto* fit = grains.add_subcommand(
      "fit-sh",
      "fit spherical harmonics to a grain mesh (STL, OBJ, PLY; metres) and write them as an SH file.\n"
      "Rays from the mesh's volume centroid along (2N+1)(4N+1) quadrature directions (Gauss-Legendre in\n"
      "cos theta, equal steps in phi) give r(theta, phi); projecting it onto Y_nm, n <= N, is the\n"
      "least-squares fit over the sphere. Prints the RMS radial error as a fraction of the volume-equivalent\n"
      "diameter d_eq. A mesh that a ray from its centroid crosses more than once is not star-shaped and is\n"
      "refused, naming the direction. The file's origin is the centroid; `grains import` meshes it.");
  fit->add_option("mesh", fo->mesh, "grain mesh (STL, OBJ, PLY), metres")->required();
  fit->add_option("--degree", fo->degree, "highest degree N")->check(CLI::Range(0, 100))->capture_default_str();
  fit->add_option("--out", fo->out, "SH file to write (default: the mesh's name with .dat)");
  fit->add_option("--unit", fo->unit, "metres per unit of r in the file written (1e-3: millimetres, as VCCTL's)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();

  auto so = std::make_shared<SpectrumOptions>();
  auto* spectrum = grains.add_subcommand(
      "spectrum",
      "a sand's shape from its grains, written as TOML: per degree n the mean and standard deviation over\n"
      "the grains of A_n / A_0, A_n = sqrt(sum_m |a_nm|^2) (the amplitude of degree n, unchanged by\n"
      "rotation; A_2 is elongation, higher n ever finer relief), and the mean, standard deviation, minimum\n"
      "and maximum of the volume-equivalent diameter (m), roundness, sphericity, elongation, flatness and\n"
      "convexity that `grains stats` measures. SH files (.dat) are meshed at --faces; meshes are fitted\n"
      "to --degree (as fit-sh) for the spectrum and measured as they are. With two grains or more it also\n"
      "writes [model], the set's shape model for `grains generate --spectrum`: the grains turned into their\n"
      "principal frames, their coefficients of degree <= --model-degree divided by a_00, and the mean and the\n"
      "first --components principal components of those (with the spread of the grains' scores along each).");
  spectrum->add_option("files", so->inputs, "grain files (.dat, .stl, .obj, .ply), or folders of them")->required();
  spectrum->add_option("--out", so->out, "TOML file to write, e.g. SAND.toml")->required();
  add_sh_file_options(*spectrum, so->faces, so->sh);
  spectrum->add_option("--degree", so->degree, "degree of the fit of mesh files")
      ->check(CLI::Range(0, 100))
      ->capture_default_str();
  spectrum->add_option("--model-degree", so->model_degree,
                       "highest degree K of the shape model written as [model] (the set's mean shape and principal "
                       "components, grains aligned to their principal frames); -1: no model")
      ->check(CLI::Range(-1, 100))
      ->capture_default_str();
  spectrum->add_option("--components", so->components,
                       "principal components the model keeps (at most grains - 1); fewer keep less of each grain")
      ->check(CLI::Range(0, 1000))
      ->capture_default_str();

  return [import, fit, spectrum, im, fo, so]() {
    if (*import) return run_import(*im);
    if (*fit) return run_fit(*fo);
    if (*spectrum) return run_spectrum(*so);
    return -1;
  };
}

}  // namespace grainlab::apps
