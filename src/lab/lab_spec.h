// Everything a lab test run needs, as plain values (SI units): the settings
// every test shares (grains, material, box, specimen, consolidation,
// numerics, output) and each registered test's own (LabSpec::settings, whose
// structs and keys live with the test: lab/lab_registry.h). The io layer
// fills it from a TOML file (io/config.h); the lab runs it (make_lab_test).
// Defaults are the embedded demo: a small box of rounded grains sheared to
// 10 % strain under 100 kPa: 8.5 x 8.5 x 5.1 mm, 10 x 6 largest grains
// (ASTM D3080), about 1230 grains of 200 faces, Dr 0.9 on their own index
// void ratios (io/embedded_indices.h).
#pragma once

#include "dynamics/contact_law.h"
#include "dynamics/material.h"

#include <any>
#include <cstdint>
#include <map>
#include <string>
#include <typeindex>
#include <vector>

namespace grainlab {

struct GrainsSpec {
  std::string preset = "rounded";      // glass-beads | rounded | sub-angular | angular
  std::string folder;                  // if set: import every STL/OBJ/PLY/.dat (SH) here instead
  int shapes = 24;                     // distinct shapes in the library (grains reuse them, scaled)
  int faces = 200;                     // face budget per grain shape (the paper's scans: 2000; 200 keeps
                                       // the demo under 10 minutes on 2 cores)
  double d_min = 0.707e-3;             // m, sieve range (passing #20, retained on #25)
  double d_max = 0.841e-3;             // m
  double convexity = 1.0;              // generated grains: volume / hull volume (< 1 presses dents in; 0.8-1)
  std::string scan;                    // if set: a segmented CT scan's folder (`grainlab ct segment`): its grains
                                       // are placed where they were scanned and consolidated (no deposition)
  std::string scan_border = "drop";    // grains of the scan touching the image border: "drop" | "keep"
  std::string representation = "auto";  // collision shape of non-spherical grains: "hull" (convex hull),
                                         // "concave" (convex pieces, convex_decomposition.h), or "auto":
                                         // concave below convexity kConcaveBelow, hull otherwise
};

// Grains less convex than this are collided as pieces under representation "auto".
inline constexpr double kConcaveBelow = 0.98;

struct MaterialSpec {
  std::string preset;                  // crushed-limestone | griffin | ottawa | glass-beads | "" (use values below)
  ContactLaw law;  // a registered law; default hertz-material
  Material grain = [] {
    Material m;
    m.name = "grain";
    m.density = 2650;
    m.friction = 0.19;
    m.youngs_modulus = 4e9;
    m.poisson_ratio = 0.3;
    m.restitution = 0.5;
    m.k_n = 1e12;
    m.k_t = 8e11;
    m.gamma_n = 40;
    m.gamma_t = 20;
    return m;
  }();
  double wall_friction = 0.0;          // box walls and cap (lubricated, as in the lab)
};

struct BoxSpec {
  double length = 8.5e-3;   // m, along the shear direction x
  double width = 8.5e-3;    // m, y
  double height = 5.1e-3;   // m, specimen height after preparation (target): 6 x d_max (ASTM D3080)
  double gap = 0.3e-3;      // m, opening between the lower and upper halves
};

struct SpecimenSpec {
  double relative_density = 0.9;   // target Dr = (e_max - e)/(e_max - e_min) on the indices below
  std::string indices = "own";     // "own": Dr on the grains' own index voids (own_e_min/own_e_max, measured
                                   // by `grainlab grains index` or by the run when not given; the default
                                   // grains' are embedded, io/embedded_indices.h); "lab": Dr on the lab's
                                   // e_min/e_max of the real sand (docs/direct_shear.md, "Whose Dr")
  double own_e_max = 0;            // the grains' own loosest void ratio; 0 = measure it (lab/index_densities.h)
  double own_e_min = 0;            // the grains' own densest void ratio; 0 = measure it
  double e_max = 0.75;             // lab index void ratios of the sand (Ottawa sand, paper section 3)
  double e_min = 0.52;
  double void_ratio = -1;          // if > 0: target void ratio, overrides Dr
  double tolerance = 0.02;         // accepted |e - e_target| (void ratio and lab-index targets)
  double relative_density_tolerance = 0.05;  // accepted |Dr - Dr_target| (own-index targets)
  double deposition_friction = -1;  // inter-grain friction while raining and compacting (lower: denser);
                                    // -1: chosen by the preparation search (lab/preparation_search.h),
                                    // which `grainlab run` runs, its first trial at the grain class's
                                    // measured friction (lab/deposition_friction.h: the default rounded
                                    // grains' 0.032 gives own Dr 0.92 in the default box); a test built
                                    // without the search deposits at that first friction
  std::string from;  // a specimen.bin another run wrote as its loading began: start from that
                     // specimen instead of preparing one (same grains, box, seed, test, stress and
                     // density scaling; the material and the loading may differ). "" = prepare
};

struct ConsolidationSpec {
  double normal_stress = 100e3;     // Pa
  double tolerance = 0.01;          // relative stress error accepted
  double max_unbalanced = 0.01;     // unbalanced-force ratio accepted at rest (each grain's resultant
                                    // averaged over the 1000 calm steps; with the kinetic energy)
};

struct NumericsSpec {
  double time_step = 0;             // s; 0 = time_step_fraction x critical
  double time_step_fraction = 0.4;  // of a conservative critical step (Hertz stiffness at 1 % overlap,
                                    // worst-case lever arm): about 0.25 of the real one at 100 kPa
  double density_scaling = 0;       // multiplies inertia (not weight); 0 = automatic
  double inertial_number = 9e-4;    // target I = gamma_dot d sqrt(rho S / p) when speed = 0: below
                                    // 1e-3 (quasi-static) with room for the stress to dip
  int threads = 0;                  // 0 = automatic: up to all cores, timed (core/thread_tuner.h)
};

struct OutputSpec {
  std::string folder = "runs/direct_shear";
  double strain_interval = 0.001;   // sample every this much shear strain
  double checkpoint_interval = 60;  // s of wall-clock time between checkpoints
  double snapshot_interval = 0.02;  // ParaView snapshot every this much shear strain; 0 = first and last only
};

struct LabSpec {
  std::string test = "direct-shear";  // the lab test (lab/lab_registry.cpp): direct-shear | oedometer | triaxial
  GrainsSpec grains;
  MaterialSpec material;
  BoxSpec box;
  SpecimenSpec specimen;
  ConsolidationSpec consolidation;
  NumericsSpec numerics;
  OutputSpec output;
  std::uint64_t seed = 1;

  // A registered test's own settings (its struct, e.g. OedometerSpec of
  // lab/oedometer.h), its defaults until set. Every test's are kept: a
  // config holds them all.
  template <typename Settings>
  Settings& settings() {
    std::any& a = test_settings_[typeid(Settings)];
    if (!a.has_value()) a = Settings{};
    return std::any_cast<Settings&>(a);
  }
  template <typename Settings>
  const Settings& settings() const {
    static const Settings defaults{};
    const auto it = test_settings_.find(typeid(Settings));
    return it == test_settings_.end() ? defaults : std::any_cast<const Settings&>(it->second);
  }
  // Every test's own settings back to their defaults.
  void reset_test_settings() { test_settings_.clear(); }

  // True when the target Dr is on the grains' own indices (not the lab's, not a void ratio).
  bool targets_own_indices() const { return specimen.void_ratio <= 0 && specimen.indices == "own"; }
  // True when the grains' own index void ratios are known.
  bool own_indices_known() const { return specimen.own_e_min > 0 && specimen.own_e_max > specimen.own_e_min; }

  // Target void ratio from Dr (on the own or the lab indices) or the explicit
  // value. Own-index targets are bulk void ratios (away from the walls,
  // lab/packing_density.h), the others the whole specimen's.
  double target_void_ratio() const {
    if (specimen.void_ratio > 0) return specimen.void_ratio;
    const bool own = specimen.indices == "own";
    const double hi = own ? specimen.own_e_max : specimen.e_max, lo = own ? specimen.own_e_min : specimen.e_min;
    return hi - specimen.relative_density * (hi - lo);
  }

 private:
  std::map<std::type_index, std::any> test_settings_;
};

}  // namespace grainlab
