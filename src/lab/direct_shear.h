// The virtual direct shear test (ASTM D3080 in spirit; paper sections 3-5),
// built on the lab kit: the box of lab/shear_box.h, the specimen of
// lab/specimen.h, the servo of lab/stress_servo.h, the rest criteria of
// lab/rest_criteria.h. The shear plane is at z = H/2 for a specimen of
// height H; the upper half moves along +x, the cap rides with it in x and is
// servo-controlled in z.
//
// Protocol (phases):
//   Deposit      grains placed on a loose lattice rain under 100 g gravity with
//                the deposition friction until they are at rest;
//   Compact      the cap comes down and the servo brings the normal stress to the
//                target, still with the deposition friction; the void ratio
//                reached is checked against the target (RunError if it misses);
//   Consolidate  the test friction is back (the Model's: the deposition
//                settings were phase overrides) and the servo holds the stress
//                until the specimen is at rest again; the void ratio is checked
//                again (a specimen deposited with more friction than the test's
//                collapses part way here) and is the specimen's e and Dr;
//   Shear        the upper half moves at constant speed to the final strain, the
//                cap holding the normal stress. A sample is recorded every
//                output.strain_interval of shear strain.
// Rest: the compaction accepts a 5 % stress error and skips the unbalanced
// force ratio; the consolidation asks the configured tolerance and the
// unbalanced-force ratio averaged over its whole calm run too; both ask the
// kinetic energy small against the elastic.
//
// Measured (DESIGN.md "Walls and the direct shear box"): shear force F on the
// upper half (minus the x force the grains put on its slabs and the cap),
// normal force N on the cap, d_h, d_v, shear strain d_h / L, void ratio
// e = (L W z_cap - V_s) / V_s, coordination number 2 N_c / N_p (grain-grain
// contacts), kinetic energy, unbalanced-force ratio (mean |resultant| per grain
// over mean |contact force|) and the inertial number I = (v / H) d sqrt(rho S / sigma).
#pragma once

#include "lab/direct_shear_spec.h"
#include "lab/lab_test.h"
#include "lab/rest_criteria.h"
#include "lab/shear_box.h"
#include "lab/shear_summary.h"
#include "lab/specimen.h"
#include "lab/stress_servo.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace grainlab {

enum class ShearPhase : std::int32_t { Deposit = 0, Compact = 1, Consolidate = 2, Shear = 3, Done = 4 };
const char* shear_phase_name(ShearPhase p);

// Column names (with units) of the series recorded during shear.
const std::vector<std::string>& shear_series_columns();

class DirectShearTest final : public LabTest {
 public:
  // Builds the grains, the model, the walls and the loose initial lattice.
  explicit DirectShearTest(const DirectShearSpec& spec);

  // LabTest.
  const DirectShearSpec& spec() const override { return spec_; }
  World& world() override { return world_; }
  const World& world() const override { return world_; }
  double time_step() const override { return dt_; }
  bool advance(int max_steps) override;
  int phase_index() const override { return static_cast<int>(p_.phase); }
  std::string phase_name() const override { return shear_phase_name(p_.phase); }
  bool loading() const override { return p_.phase == ShearPhase::Shear; }
  bool done() const override { return p_.phase == ShearPhase::Done; }
  std::int64_t loading_start_step() const override { return phase_step(ShearPhase::Shear); }
  double progress() const override { return shear_strain(); }
  double final_progress() const override { return spec_.shear.final_strain; }
  std::string progress_label() const override { return "shear strain"; }
  std::string status_line() const override;
  std::string phase_note() const override;
  std::string result_line() const override;
  std::vector<std::string> series_columns() const override;
  const std::vector<std::vector<double>>& series() const override { return p_.rows; }
  void set_sample_observer(std::vector<std::string> columns, SampleObserver observer) override;
  const std::vector<BodyState>& reference() const override { return p_.reference; }
  std::vector<SummaryValue> summary() const override;
  double specimen_volume() const override { return box_area() * world_.state.walls[Cap].x.z(); }
  double boundary_stress() const override { return normal_stress(); }
  BandGeometry band_geometry() const override;
  std::vector<std::uint8_t> save() const override;
  void load(std::span<const std::uint8_t> bytes) override;

  // Direct shear measurements and settings.
  ShearPhase phase() const { return p_.phase; }
  double shear_speed() const { return shear_speed_; }
  double solid_volume() const { return specimen_.solid_volume; }   // m^3
  double mean_diameter() const { return specimen_.mean_diameter; } // m, volume-equivalent
  // m/s: the fastest a servo moves a wall while preparing, 2e-4 grain diameters per step.
  double servo_speed_limit() const { return 2e-4 * mean_diameter() / dt_; }
  double shear_strain() const;
  double normal_stress() const { return normal_force() / box_area(); }  // Pa, on the cap
  double shear_force() const;    // N, on the upper half
  double normal_force() const { return world_.state.walls[Cap].force.z(); }  // N, on the cap
  double void_ratio() const;
  double coordination_number() const;
  double inertial_number() const;
  double cap_displacement() const;  // m, since the start of shear (up is positive)
  double servo_integral() const { return servo_.integral(); }  // Pa
  ShearSummary shear_summary() const { return summarise_shear(p_.rows); }
  // The specimen's void ratio (whole specimen): at the start of shear (after
  // consolidation, where a specimen deposited with more friction than the
  // test's collapses part way), before that at the end of compaction.
  double achieved_void_ratio() const;
  double achieved_bulk_void_ratio() const { return p_.compacted_bulk_void_ratio; }  // away from the walls
  // Dr on the target's indices: own (bulk e after compaction), else lab (achieved_void_ratio()).
  double achieved_relative_density() const;
  // Dr after compaction on the grains' own indices (bulk e); NaN if they are unknown.
  double achieved_own_relative_density() const;
  // Dr after compaction on the lab's indices (whole-specimen e).
  double achieved_lab_relative_density() const;
  // Void ratio now in the bulk (lab/packing_density.h: kBulkMarginDiameters from walls, floor and cap).
  double bulk_void_ratio() const;
  // Lets compaction end at any density (for trial preparations; the caller judges them).
  void accept_any_density() { accept_any_density_ = true; }
  // Ends the test (phase Done) when consolidation is at rest, without
  // shearing: the preparation of another test in this box (lab/oedometer.h).
  void end_after_consolidation() { end_after_consolidation_ = true; }
  std::int64_t phase_step(ShearPhase p) const { return p_.phase_start_step[static_cast<int>(p)]; }

 private:
  struct Progress {
    ShearPhase phase = ShearPhase::Deposit;
    RestRun rest;
    double compacted_void_ratio = 0;
    double compacted_bulk_void_ratio = 0;
    double cap_z_at_shear = 0;
    double upper_x_at_shear = 0;
    double next_sample_strain = 0;
    std::array<std::int64_t, 5> phase_start_step{};
    std::vector<std::vector<double>> rows;
    std::vector<BodyState> reference;  // grains at the start of shear
  };

  void enter(ShearPhase p);
  void apply_phase_overrides();
  bool check_rest(ShearPhase p);
  // Throws RunError naming the grain, where and when, if one left the box.
  void check_grains_inside() const;
  // Throws RunError (what was reached, how to fix it) if the whole (lab-index
  // or void-ratio target) or bulk (own-index target) void ratio misses the target.
  void check_preparation(double e_whole, double e_bulk, const char* when) const;
  void record_sample();
  double box_area() const { return spec_.box.length * spec_.box.width; }

  DirectShearSpec spec_;
  World world_;
  Specimen specimen_;
  Progress p_;
  StressServo servo_{Cap, 0, 0, 0};  // set up once dt is known
  double dt_ = 0;
  double shear_speed_ = 0;
  Index grain_material_ = 0;
  bool accept_any_density_ = false;
  bool end_after_consolidation_ = false;
  std::vector<std::string> observer_columns_;
  SampleObserver observer_;
};

}  // namespace grainlab
