// Specimen preparation, the first phases of every lab test: the World
// (grains, materials, the walls of lab/shear_box.h, the time step), the
// loose placement of lab/specimen.h (or a scan's grains where they were
// scanned, lab/scanned_specimen.h), and the phases
//   Deposit      grains rain under 100 g gravity with the deposition friction
//                until they are at rest;
//   Compact      the cap comes down and its servo (lab/stress_servo.h) brings
//                the normal stress to consolidation.normal_stress, still with
//                the deposition friction; the void ratio reached is checked
//                against the target (RunError if it misses);
//   Consolidate  the test friction is back (the deposition settings were phase
//                overrides) and the servo holds the stress until the specimen
//                is at rest again; the void ratio is checked again (a specimen
//                deposited with more friction than the test's collapses part
//                way here) and is the specimen's e and Dr;
//   Prepared     done: the test that holds it loads the specimen its own way.
// Rest: the compaction accepts a 5 % stress error and skips the unbalanced
// force ratio; the consolidation asks the configured tolerance and the
// unbalanced-force ratio averaged over its whole calm run too; both ask the
// kinetic energy small against the elastic.
//
// The same object is a trial of the preparation search
// (lab/preparation_search.h), a preparation of the grains' own index
// densities (lab/index_densities.h), and what a PreparationStore keeps
// (lab/preparation_store.h). It owns the World; a test steps it through
// advance() until prepared, then steps the World itself.
#pragma once

#include "core/bytes.h"
#include "dynamics/world.h"
#include "lab/lab_spec.h"
#include "lab/lab_test.h"
#include "lab/rest_criteria.h"
#include "lab/shear_box.h"
#include "lab/specimen.h"
#include "lab/stress_servo.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace grainlab {

enum class PreparationPhase : std::int32_t { Deposit = 0, Compact = 1, Consolidate = 2, Prepared = 3 };
const char* preparation_phase_name(PreparationPhase p);

class SpecimenPreparation {
 public:
  // Builds the World (its thread count from spec.numerics.threads), the
  // grains, the model, the walls (spec.box) and the loose initial lattice.
  explicit SpecimenPreparation(const LabSpec& spec);
  SpecimenPreparation(const SpecimenPreparation&) = delete;
  SpecimenPreparation& operator=(const SpecimenPreparation&) = delete;

  const LabSpec& spec() const { return spec_; }
  World& world() { return world_; }
  const World& world() const { return world_; }
  double time_step() const { return dt_; }

  // Advances by up to max_steps steps; returns early at a phase change.
  // False once prepared. Throws RunError if a phase misses its target or
  // does not come to rest.
  bool advance(int max_steps);
  PreparationPhase phase() const { return p_.phase; }
  bool prepared() const { return p_.phase == PreparationPhase::Prepared; }
  std::string phase_name() const { return preparation_phase_name(p_.phase); }
  std::int64_t phase_step(PreparationPhase p) const { return p_.phase_start_step[static_cast<int>(p)]; }

  // The cap's servo holds consolidation.normal_stress while compacting and
  // consolidating; once prepared only while hold_cap(true) (a direct shear
  // keeps the normal stress while it shears).
  void hold_cap(bool hold) { hold_cap_ = hold; }
  double servo_integral() const { return servo_.integral(); }  // Pa
  // m/s: the fastest a servo moves a wall while preparing, 2e-4 grain diameters per step.
  double servo_speed_limit() const { return 2e-4 * mean_diameter() / dt_; }
  // Lets compaction end at any density (trial and index preparations; the caller judges them).
  void accept_any_density() { accept_any_density_ = true; }

  // Measurements.
  const Specimen& specimen() const { return specimen_; }
  double solid_volume() const { return specimen_.solid_volume; }    // m^3
  double mean_diameter() const { return specimen_.mean_diameter; }  // m, volume-equivalent
  double box_area() const { return spec_.box.length * spec_.box.width; }
  double normal_force() const { return world_.state.walls[Cap].force.z(); }  // N, on the cap
  double normal_stress() const { return normal_force() / box_area(); }       // Pa, on the cap
  double void_ratio() const;       // now, whole specimen (below the cap)
  double bulk_void_ratio() const;  // now, in the bulk (lab/packing_density.h)
  double coordination_number() const;  // 2 N_c / N_p (touching grain pairs)
  // The cap's height at the end of consolidation (0 before).
  double consolidated_height() const { return p_.consolidated_height; }
  // The specimen's void ratio (whole specimen): after consolidation, before that after compaction.
  double achieved_void_ratio() const;
  double achieved_bulk_void_ratio() const { return p_.compacted_bulk_void_ratio; }  // after compaction
  double compacted_void_ratio() const { return p_.compacted_void_ratio; }
  // Dr on the target's indices: own (bulk e after compaction), else lab (achieved_void_ratio()).
  double achieved_relative_density() const;
  // Dr after compaction on the grains' own indices (bulk e); NaN if they are unknown.
  double achieved_own_relative_density() const;
  // Dr on the lab's indices (achieved_void_ratio()).
  double achieved_lab_relative_density() const;

  // Throws RunError naming the grain, where and when, if one left the box
  // (`phase`: the test's phase name; `shearing`: the gap is open).
  void check_grains_inside(const std::string& phase, bool shearing) const;

  // A progress line ("sigma 99.8 kPa  e 0.712").
  std::string status_line() const;
  // The note printed as consolidation begins ("prepared: void ratio ..."), else "".
  std::string phase_note() const;
  // run.json values: the grain size and group "preparation".
  std::vector<SummaryValue> summary() const;
  // run.json values of how the grains are collided (group "grain_shapes") and of a scan ("scan").
  std::vector<SummaryValue> shape_summary() const;

  // The preparation's own state (the World's State is saved separately);
  // load applies the phase's overrides.
  void save(ByteWriter& out) const;
  void load(ByteReader& in);
  // The same as one block of bytes (a PreparationStore keeps these).
  std::vector<std::uint8_t> save() const;
  void load(std::span<const std::uint8_t> bytes);

 private:
  struct Progress {
    PreparationPhase phase = PreparationPhase::Deposit;
    RestRun rest;
    double compacted_void_ratio = 0;
    double compacted_bulk_void_ratio = 0;
    double consolidated_height = 0;
    std::array<std::int64_t, 4> phase_start_step{};
  };

  void enter(PreparationPhase p);
  void apply_phase_overrides();
  bool check_rest(PreparationPhase p);
  // Throws RunError (what was reached, how to fix it) if the whole (lab-index
  // or void-ratio target) or bulk (own-index target) void ratio misses the target.
  void check_preparation(double e_whole, double e_bulk, const char* when) const;

  LabSpec spec_;
  World world_;
  Specimen specimen_;
  Progress p_;
  StressServo servo_{Cap, 0, 0, 0};  // set up once dt is known
  double dt_ = 0;
  Index grain_material_ = 0;
  bool accept_any_density_ = false;
  bool hold_cap_ = false;
};

}  // namespace grainlab
