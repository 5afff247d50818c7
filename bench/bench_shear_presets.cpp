// Direct shear of the paper's four sands at one small size, and the damping
// sensitivity of its Appendix 2. Not a test: it prints figures.
//
// Part 1, per sand preset (crushed limestone = angular grains, Griffin =
// sub-angular, Ottawa = rounded, glass beads = spheres; Table 1 values):
// achieved void ratio and Dr, peak friction angle (Eq. 18), peak dilation
// angle (Eq. 19) and wall time. The paper's trend: both peaks fall as the
// grains get rounder.
// Part 2, glass beads with the paper's user Hertz law and gamma_n/gamma_t =
// 20/10, 40/20, 80/40: peak stress ratio and final cap displacement, and
// their spread over the three.
//
//   build/bench_shear_presets [--strain S] [--box MM] [--only presets|damping]
//
// Every run uses the same preparation (deposition friction 0.12 under 100 g,
// then the cap servo), so the achieved density differs by shape, as it does
// for one pluviation procedure in the lab; the target tolerance is open.
#include "core/wait_policy.h"
#include "dynamics/laws/registry.h"
#include "core/error.h"
#include "core/parallel.h"
#include "core/timer.h"
#include "lab/direct_shear.h"
#include "lab/sand_presets.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

using namespace grainlab;

namespace {

struct Options {
  double strain = 0.06;
  double box_mm = 5.0;
  std::string only;
};

LabSpec small_spec(const Options& o, const std::string& sand) {
  LabSpec spec;
  apply_sand_preset(spec, sand);
  spec.box.length = spec.box.width = o.box_mm * 1e-3;
  spec.box.height = 0.7 * o.box_mm * 1e-3;
  spec.grains.shapes = 12;
  spec.grains.faces = 200;
  spec.specimen.tolerance = 1.0;  // report what one procedure reaches
  spec.specimen.indices = "lab";  // Dr on the sand's lab indices: no own index measurement here
  spec.specimen.deposition_friction = 0.12;
  spec.settings<ShearSpec>().final_strain = o.strain;
  spec.numerics.time_step_fraction = 0.4;
  spec.seed = 3;
  return spec;
}

struct Outcome {
  double e = 0, dr = 0, wall_s = 0, final_dv = 0;
  ShearSummary summary;
  std::size_t grains = 0;
};

Outcome run(const LabSpec& spec) {
  Stopwatch clock;
  DirectShearTest t(spec);
  while (t.advance(1000)) {
  }
  Outcome o;
  o.e = t.achieved_void_ratio();
  o.dr = t.achieved_relative_density();
  o.summary = t.shear_summary();
  o.final_dv = t.cap_displacement();
  o.grains = t.world().model.bodies.size();
  o.wall_s = clock.seconds();
  return o;
}

void presets(const Options& o) {
  fmt::print("Four sands, box {:.1f} x {:.1f} x {:.1f} mm, sheared to {:.0f} % strain, 100 kPa\n", o.box_mm,
             o.box_mm, 0.7 * o.box_mm, 100 * o.strain);
  fmt::print("{:<18} {:<12} {:>6} {:>7} {:>6} {:>10} {:>10} {:>9}\n", "sand", "grains", "count", "e", "Dr %",
             "peak phi", "peak psi", "wall s");
  for (const char* sand : {"crushed-limestone", "griffin", "ottawa", "glass-beads"}) {
    const LabSpec spec = small_spec(o, sand);
    const Outcome r = run(spec);
    fmt::print("{:<18} {:<12} {:>6} {:>7.3f} {:>6.0f} {:>9.1f}° {:>9.1f}° {:>9.0f}\n", sand, spec.grains.preset,
               r.grains, r.e, 100 * r.dr, r.summary.peak_friction_angle_deg, r.summary.peak_dilation_angle_deg,
               r.wall_s);
    std::fflush(stdout);
  }
}

void damping(const Options& o) {
  fmt::print("\nDamping sensitivity (Appendix 2): glass beads, contact_law = hertz (k_n 1e12, k_t 8e11)\n");
  fmt::print("{:>8} {:>8} {:>12} {:>16} {:>9}\n", "gamma_n", "gamma_t", "peak F/N", "final d_v (um)", "wall s");
  std::vector<double> peaks, dvs;
  for (const auto& [gn, gt] : {std::pair{20.0, 10.0}, std::pair{40.0, 20.0}, std::pair{80.0, 40.0}}) {
    LabSpec spec = small_spec(o, "glass-beads");
    spec.material.law = contact_law<HertzUserLaw>();
    spec.material.grain.gamma_n = gn;
    spec.material.grain.gamma_t = gt;
    Outcome r;
    try {
      r = run(spec);
    } catch (const RunError& e) {
      fmt::print("{:>8.0f} {:>8.0f}  stopped: {}\n", gn, gt, e.what());
      continue;
    }
    peaks.push_back(r.summary.peak_stress_ratio);
    dvs.push_back(r.final_dv * 1e6);
    fmt::print("{:>8.0f} {:>8.0f} {:>12.3f} {:>16.1f} {:>9.0f}\n", gn, gt, r.summary.peak_stress_ratio,
               r.final_dv * 1e6, r.wall_s);
    std::fflush(stdout);
  }
  if (peaks.size() < 2) return;
  const auto spread = [](const std::vector<double>& v) {
    return *std::max_element(v.begin(), v.end()) - *std::min_element(v.begin(), v.end());
  };
  double mean = 0;
  for (double p : peaks) mean += p / peaks.size();
  fmt::print("spread: peak F/N {:.3f} ({:.1f} % of the mean), final d_v {:.1f} um\n", spread(peaks),
             100 * spread(peaks) / mean, spread(dvs));
}

}  // namespace

int main(int argc, char** argv) {
  grainlab::use_passive_wait_by_default(argv);  // as grainlab runs (core/wait_policy.h)
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const bool has_value = i + 1 < argc;
    if (a == "--strain" && has_value) o.strain = std::stod(argv[++i]);
    else if (a == "--box" && has_value) o.box_mm = std::stod(argv[++i]);
    else if (a == "--only" && has_value) o.only = argv[++i];
    else {
      fmt::print(stderr, "usage: bench_shear_presets [--strain S] [--box MM] [--only presets|damping]\n");
      return 2;
    }
  }
  fmt::print("threads: {}\n", thread_count());
  if (o.only.empty() || o.only == "presets") presets(o);
  if (o.only.empty() || o.only == "damping") damping(o);
  return 0;
}
