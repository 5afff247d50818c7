// `grainlab grains`: generate synthetic grain sets and measure grain shapes.
#include "apps/commands.h"
#include "core/error.h"
#include "core/timer.h"
#include "geometry/mesh_check.h"
#include "geometry/mesh_io.h"
#include "geometry/shape_metrics.h"
#include "grains/grain_set.h"
#include "grains/sh_sands.h"
#include "lab/grain_library.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace grainlab::apps {

namespace {

namespace fs = std::filesystem;

struct GenerateOptions {
  std::string preset;
  std::string spectrum;
  std::string method;
  int count = 50;
  std::uint64_t seed = 1;
  std::string out;
  int faces = 2000;
  std::optional<double> roundness, elongation, flatness;
  double convexity = 1.0;
  double d_min = 0.707e-3, d_max = 0.841e-3;
};

struct StatsOptions {
  std::vector<std::string> inputs;
  std::string representation = "auto";
  int faces = 2000;  // SH files: triangles of the mesh
  ShOptions sh;      // SH files: unit, degrees kept
};

// Mean, minimum and maximum of one column.
struct Summary {
  double mean = 0, min = 0, max = 0;
};

Summary summarise(const std::vector<double>& v) {
  Summary s{0, *std::min_element(v.begin(), v.end()), *std::max_element(v.begin(), v.end())};
  for (double x : v) s.mean += x / v.size();
  return s;
}

// One line describing a set of measured grains.
std::string set_summary(const std::vector<ShapeMetrics>& m) {
  std::vector<double> d, r, sph, e, f, c;
  for (const ShapeMetrics& s : m) {
    d.push_back(s.equivalent_diameter * 1e3);
    r.push_back(s.roundness);
    sph.push_back(s.sphericity);
    e.push_back(s.elongation);
    f.push_back(s.flatness);
    c.push_back(s.convexity);
  }
  const Summary sd = summarise(d), sr = summarise(r), ss = summarise(sph);
  return fmt::format("{} grains, equivalent diameter {:.3f} mm ({:.3f}-{:.3f}), roundness {:.2f} ({:.2f}-{:.2f}), "
                     "sphericity {:.3f} ({:.3f}-{:.3f}), elongation {:.2f}, flatness {:.2f}, convexity {:.3f}",
                     m.size(), sd.mean, sd.min, sd.max, sr.mean, sr.min, sr.max, ss.mean, ss.min, ss.max,
                     summarise(e).mean, summarise(f).mean, summarise(c).mean);
}

int run_generate(const GenerateOptions& o) {
  if (!o.spectrum.empty()) return run_generate_from_spectrum(o.spectrum, o.method, o.count, o.seed, o.out, o.faces);
  if (o.preset.empty()) input_error("grains generate needs --preset NAME or --spectrum SAND.toml");
  const bool sh = find_sh_sand(o.preset) != nullptr;
  GeneratorSpec spec = sh ? GeneratorSpec{} : preset_spec(parse_grain_preset(o.preset));
  spec.faces = o.faces;
  if (o.roundness) spec.roundness = *o.roundness;
  if (o.elongation) spec.elongation = *o.elongation;
  if (o.flatness) spec.flatness = *o.flatness;
  spec.convexity = o.convexity;
  Stopwatch clock;
  const GrainSet set = sh ? generate_sh_grain_set(o.preset, o.count, o.seed, SieveRange{o.d_min, o.d_max}, o.faces)
                          : generate_grain_set(spec, o.count, o.seed, SieveRange{o.d_min, o.d_max});
  const double seconds = clock.seconds();
  std::error_code ec;
  fs::create_directories(o.out, ec);
  if (ec) input_error("cannot create output folder '{}': {}", o.out, ec.message());
  std::vector<ShapeMetrics> metrics;
  for (std::size_t i = 0; i < set.meshes.size(); ++i) {
    write_stl(set.meshes[i], fs::path(o.out) / (set.names[i] + ".stl"));
    metrics.push_back(shape_metrics(set.meshes[i]));
  }
  fmt::print("wrote {} {} grains ({} faces each{}) to {} in {:.2f} s\n", set.meshes.size(), o.preset,
             set.meshes.front().faces.size(), set.spheres ? ", spheres" : "", o.out, seconds);
  fmt::print("  {}\n", set_summary(metrics));
  fmt::print("  sizes: intermediate principal dimension in [{:.3f}, {:.3f}] mm; measure with "
             "`grainlab grains stats {}`\n",
             o.d_min * 1e3, o.d_max * 1e3, o.out);
  return 0;
}

int run_stats(const StatsOptions& o) {
  // Sets: each folder argument, and the parent folder of each file argument.
  std::map<std::string, std::vector<fs::path>> sets;
  std::vector<std::string> set_order;
  auto add = [&](const std::string& set, const fs::path& file) {
    if (!sets.count(set)) set_order.push_back(set);
    sets[set].push_back(file);
  };
  for (const std::string& in : o.inputs) {
    const fs::path p(in);
    if (fs::is_directory(p)) {
      std::vector<fs::path> files;
      for (const auto& e : fs::directory_iterator(p)) {
        if (e.is_regular_file() && is_grain_file(e.path())) files.push_back(e.path());
      }
      std::sort(files.begin(), files.end());
      if (files.empty()) input_error("'{}' holds no .stl, .obj, .ply or .dat (spherical-harmonic) file", in);
      for (const auto& f : files) add(in, f);
    } else if (fs::is_regular_file(p)) {
      add(p.parent_path().empty() ? "." : p.parent_path().string(), p);
    } else {
      input_error("'{}' is neither a mesh file nor a folder", in);
    }
  }
  fmt::print("file,volume_m3,surface_area_m2,equivalent_diameter_m,long_axis_m,intermediate_axis_m,"
             "short_axis_m,elongation,flatness,sphericity,convexity,roundness,simulated_as,pieces,"
             "collision_excess\n");
  for (const std::string& set : set_order) {
    std::vector<ShapeMetrics> metrics;
    int as_pieces = 0;
    for (const fs::path& file : sets[set]) {
      std::vector<std::string> notes;
      const TriMesh mesh = load_grain_file(file, o.faces, o.sh, &notes);
      for (const std::string& note : notes) fmt::print(stderr, "grainlab grains stats: note: {}\n", note);
      const ShapeMetrics s = shape_metrics(mesh);
      // What a run would collide (grains.representation): the hull, or convex pieces.
      std::size_t pieces = 1;
      double excess = 1 / s.convexity - 1;  // the hull's
      if (collides_as_pieces(o.representation, s.convexity)) {
        DecompositionOptions d;
        d.max_pieces = kMaxCompoundPieces;
        const ConvexDecomposition dec = decompose_convex(mesh, d);
        pieces = dec.pieces.size();
        excess = dec.excess();
      }
      as_pieces += pieces > 1;
      fmt::print("{},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e},{:.4f},{:.4f},{:.4f},{:.4f},{:.4f},{},{},{:.4f}\n",
                 file.string(), s.volume, s.surface_area, s.equivalent_diameter, s.long_axis,
                 s.intermediate_axis, s.short_axis, s.elongation, s.flatness, s.sphericity, s.convexity,
                 s.roundness, pieces > 1 ? "pieces" : "hull", pieces, excess);
      metrics.push_back(s);
    }
    std::fflush(stdout);
    fmt::print(stderr, "{}: {}; simulated as convex pieces: {} of {} (grains.representation = {})\n", set,
               set_summary(metrics), as_pieces, metrics.size(), o.representation);
  }
  return 0;
}

}  // namespace

Command add_grains_command(CLI::App& app) {
  auto g = std::make_shared<GenerateOptions>();
  auto s = std::make_shared<StatsOptions>();
  auto* grains = app.add_subcommand(
      "grains", "generate synthetic sand grains, measure grain meshes (size, sphericity, Wadell roundness), measure a "
      "grain set's own index void ratios (e_min, e_max), or import, fit and summarise grains described by "
      "spherical harmonics");
  grains->require_subcommand(1);

  std::string presets = "angularity class, standing in for the paper's sands:";
  for (GrainPreset p : {GrainPreset::GlassBeads, GrainPreset::Rounded, GrainPreset::SubAngular,
                        GrainPreset::Angular}) {
    presets += "\n  " + grain_preset_description(p);
  }
  presets += "\nor a spherical-harmonic sand (shape model of 16 CT-scanned grains, method shape-model; --roundness, "
             "--elongation, --flatness and --convexity do not apply):";
  for (const ShSand& s : sh_sands()) presets += "\n  " + s.name + ": " + s.description;
  auto* gen = grains->add_subcommand(
      "generate",
      "write COUNT synthetic grains of a preset, or drawn from a sand's spectrum, as binary STL files\n"
      "(metres), one per grain.\n"
      "With --preset, each grain is a random convex polytope whose corners are rounded by a sphere (then dented,\n"
      "with --convexity below 1); roundness is Wadell's (mean corner radius / largest inscribed\n"
      "circle, averaged over the three principal projections), elongation is I/L and flatness S/I\n"
      "(L >= I >= S principal dimensions).\n"
      "Sizes (the intermediate dimension I, what a sieve sorts by) spread evenly over [d-min, d-max].\n"
      "With --spectrum instead, each grain is a random spherical-harmonic surface. --method shape-model (the\n"
      "default when the file has a [model]): its degrees <= K are the set's mean shape plus each principal\n"
      "component of the set times a normal score of that component's spread (the grains aligned to their\n"
      "principal frames), the rest of the variance and the degrees above K with random phases as below.\n"
      "--method random-phase: per degree n an amplitude A_n/A_0 drawn from the lognormal of the spectrum's\n"
      "mean and standard deviation, spread over the 2n+1 coefficients of degree n in a random direction.\n"
      "A draw with r <= 0 somewhere is drawn again; then the grain is scaled to a volume-equivalent diameter\n"
      "drawn from the spectrum's (lognormal, clamped to its range), centred and turned into its principal\n"
      "frame. Files sh-0001.stl, ...; the generated set's shape is printed beside the measured set's.\n"
      "The same seed gives the same files, bit for bit.");
  auto* preset = gen->add_option("--preset", g->preset, presets)
                     ->check(CLI::IsMember({"glass-beads", "rounded", "sub-angular", "angular", "sh-ottawa",
                                            "sh-river", "sh-limestone"}));
  auto* spectrum = gen->add_option("--spectrum", g->spectrum,
                                   "spectrum file of a sand (TOML, from `grainlab grains spectrum`): draw random "
                                   "spherical-harmonic grains with its spectrum and sizes instead of a preset")
                       ->excludes(preset);
  gen->add_option("--method", g->method,
                  "with --spectrum: shape-model (the file's [model]: the set's principal components, the default "
                  "when it has one) or random-phase (per-degree amplitudes only, the default otherwise)")
      ->check(CLI::IsMember({"shape-model", "random-phase"}))
      ->needs(spectrum);
  gen->add_option("--count", g->count, "number of grains")->check(CLI::Range(1, 1000000))->capture_default_str();
  gen->add_option("--seed", g->seed, "random seed (same seed, same grains)")->capture_default_str();
  gen->add_option("--out", g->out, "output folder (created if missing); files <preset>-0001.stl, ... (sh-0001.stl, ... from --spectrum)")->required();
  gen->add_option("--faces", g->faces, "triangles per grain (the paper's scans: 2000)")
      ->check(CLI::Range(20, 1000000))
      ->capture_default_str();
  gen->add_option("--roundness", g->roundness, "mean Wadell roundness, (0, 1]; 1 = spheres (default: the preset's)")
      ->check(CLI::Range(0.0, 1.0));
  gen->add_option("--elongation", g->elongation, "mean I/L, (0, 1] (default: the preset's)")
      ->check(CLI::Range(0.0, 1.0));
  gen->add_option("--flatness", g->flatness, "mean S/I, (0, 1] (default: the preset's)")->check(CLI::Range(0.0, 1.0));
  gen->add_option("--convexity", g->convexity,
                  fmt::format("volume / convex hull volume, [{}, 1]: below 1 each grain gets two smooth craters "
                              "(rims 130 deg across seen from its centre, in random directions on opposite sides) "
                              "pressed in deep enough for it. A run collides such grains as their "
                              "convex pieces (grains.representation = \"auto\" below convexity 0.98; \"hull\" "
                              "collides the convex hull instead)",
                              kMinConvexity))
      ->check(CLI::Range(kMinConvexity, 1.0))
      ->capture_default_str();
  gen->add_option("--d-min", g->d_min, "smallest size (m): the retaining sieve, default #25 = 0.707e-3")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  gen->add_option("--d-max", g->d_max, "largest size (m): the passing sieve, default #20 = 0.841e-3")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  for (const char* o : {"--roundness", "--elongation", "--flatness", "--convexity", "--d-min", "--d-max"}) {
    gen->get_option(o)->excludes(spectrum);  // a spectrum sets shapes and sizes itself
  }

  auto* stats = grains->add_subcommand(
      "stats",
      "measure grain meshes (STL, OBJ, PLY; coordinates in metres) or spherical-harmonic grains (.dat, meshed\n"
      "at --faces as `grains import` does, --unit metres per unit) and print a CSV table on standard output:\n"
      "one row per grain with volume_m3, surface_area_m2, equivalent_diameter_m (equal-volume sphere),\n"
      "long/intermediate/short_axis_m (extents along the principal axes of inertia), elongation (I/L),\n"
      "flatness (S/I), sphericity (area of the equal-volume sphere / surface area), convexity\n"
      "(volume / convex hull volume) and roundness (Wadell, after Zheng & Hryciw, mean of the three\n"
      "principal projections). The last columns say what a run would collide (grains.representation):\n"
      "simulated_as is 'hull' (the convex hull) or 'pieces' (convex pieces that keep the dents; mass\n"
      "properties always come from the mesh), pieces is their number, and collision_excess is the\n"
      "volume they fill beyond the grain, as a fraction of its volume (the hull's is 1/convexity - 1).\n"
      "A one-line summary per set (folder) goes to standard error.");
  stats->add_option("files", s->inputs, "mesh files, or folders of them (each folder is one set)")->required();
  stats->add_option("--representation", s->representation,
                    "collision shape to report: auto (pieces below convexity 0.98), hull or concave")
      ->check(CLI::IsMember({"auto", "hull", "concave"}))
      ->capture_default_str();
  add_sh_file_options(*stats, s->faces, s->sh);

  const Command index = add_grains_index_command(*grains);
  const Command sh = add_grains_sh_commands(*grains);
  return [gen, stats, g, s, index, sh]() {
    if (*gen) return run_generate(*g);
    if (*stats) return run_stats(*s);
    const int rc = sh();
    return rc >= 0 ? rc : index();
  };
}

}  // namespace grainlab::apps
