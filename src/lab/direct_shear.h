// The virtual direct shear test (ASTM D3080 in spirit; paper sections 3-5).
//
// Box: inner length L (x, the shear direction), width W (y); the shear plane
// is at z = H/2 for a specimen of height H. Walls (rigid, lubricated):
//   floor        plane z = 0, normal +z
//   lower half   four slabs around the box for z < H/2 - gap/2 (fixed)
//   upper half   four slabs for z > H/2 + gap/2, moved along +x at the shear speed
//   cap          plane, normal -z, servo-controlled in z and riding with the upper half in x
// Slabs are 2.5 mm thick (thicker than the largest shear displacement of the
// default box) so that no opening appears as the halves slide.
//
// Protocol (phases):
//   Deposit      grains placed on a loose lattice rain under 100 g gravity with
//                the deposition friction until they are at rest;
//   Compact      the cap comes down and the servo brings the normal stress to the
//                target, still with the deposition friction; the void ratio
//                reached is checked against the target (RunError if it misses);
//   Consolidate  the test friction is restored and the servo holds the stress
//                until the specimen is at rest again;
//   Shear        the upper half moves at constant speed to the final strain, the
//                cap holding the normal stress. A sample is recorded every
//                output.strain_interval of shear strain.
//
// Servo (proportional-integral): v_z = G (e + I), e = sigma - sigma_target,
// I <- I + beta e each step, with G = alpha A / (k_cap dt), where k_cap is the
// summed tangent stiffness of the cap's contacts (1.5 f/delta for Hertz,
// f/delta for Hooke). If the specimen were a spring k_cap, the stress would
// change by -alpha (e + I) per step: alpha = 0.05 removes an error in about
// 1/alpha steps, slowly enough for the stress to cross the specimen. A purely
// proportional servo following a dilating specimen at speed u lags by
// e = u k_cap dt / (alpha A), a few per cent in shear; the integral term
// (beta = alpha / 10, overdamped: beta < alpha / 4) removes that lag. The cap
// never moves more than 2e-4 grain diameters per step (the speed is clamped,
// and the integral does not wind up while it is).
//
// Measured (DESIGN.md "Walls and the direct shear box"): shear force F on the
// upper half (minus the x force the grains put on its slabs and the cap),
// normal force N on the cap, d_h, d_v, shear strain d_h / L, void ratio
// e = (L W z_cap - V_s) / V_s, coordination number 2 N_c / N_p (grain-grain
// contacts), kinetic energy, unbalanced-force ratio (mean |resultant| per grain
// over mean |contact force|) and the inertial number I = (v / H) d sqrt(rho S / sigma).
#pragma once

#include "dynamics/world.h"
#include "lab/direct_shear_spec.h"

#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace grainlab {

enum class ShearPhase : std::int32_t { Deposit = 0, Compact = 1, Consolidate = 2, Shear = 3, Done = 4 };
const char* shear_phase_name(ShearPhase p);

// Column names (with units) of the series recorded during shear.
const std::vector<std::string>& shear_series_columns();

// Peak and final values of a run (paper Eqs. 18-19).
struct ShearSummary {
  double peak_friction_angle_deg = 0, strain_at_peak_friction = 0;
  double peak_dilation_angle_deg = 0, strain_at_peak_dilation = 0;
  double peak_stress_ratio = 0;
  double final_friction_angle_deg = 0, final_dilation_angle_deg = 0;  // mean over the last 10 % of strain
  double final_void_ratio = 0;
};

class DirectShearTest {
 public:
  // Builds the grains, the model, the walls and the loose initial lattice.
  explicit DirectShearTest(const DirectShearSpec& spec);

  const DirectShearSpec& spec() const { return spec_; }
  World& world() { return world_; }
  const World& world() const { return world_; }
  ShearPhase phase() const { return progress_.phase; }
  double time_step() const { return dt_; }
  double shear_speed() const { return shear_speed_; }
  double solid_volume() const { return solid_volume_; }   // m^3
  double mean_diameter() const { return mean_diameter_; } // m, volume-equivalent

  // Advances by up to max_steps steps; stops early at a phase change and after
  // recording a sample (so callers see the sampled state). Returns
  // false once the test is done. Throws RunError if preparation misses its
  // target or a phase does not converge.
  bool advance(int max_steps);

  // Measurements of the current state.
  double shear_strain() const;
  double normal_stress() const;  // Pa, on the cap
  double shear_force() const;    // N, on the upper half
  double normal_force() const;   // N, on the cap
  double void_ratio() const;
  double coordination_number() const;
  double unbalanced_force_ratio() const;
  // The same with each grain's resultant averaged over the current calm run
  // (up to 1000 steps): the static imbalance, without the ringing of stiff
  // contacts and of the packing's collective modes, which keeps the
  // instantaneous ratio of faceted grains at 0.1-0.2 in a packing at rest.
  // The consolidation's rest test uses it.
  double averaged_unbalanced_force_ratio() const;
  double inertial_number() const;
  double cap_displacement() const;  // m, since the start of shear (up is positive)

  // The series recorded so far (one row per sample, columns as
  // shear_series_columns(), then those of the sample observer if one is set).
  const std::vector<std::vector<double>>& series() const { return progress_.rows; }
  std::vector<std::string> series_columns() const;

  // An observer that appends its own values to every sample row (analysis of
  // the grains, computed by a higher layer): called with the test at the
  // sampled step. Set it before the first sample, the same on a resumed run.
  using SampleObserver = std::function<std::vector<double>(const DirectShearTest&)>;
  void set_sample_observer(std::vector<std::string> columns, SampleObserver observer);

  // The grains at the start of shear (displacements and rotations are measured
  // from it); empty before shear.
  const std::vector<BodyState>& shear_reference() const { return progress_.reference; }
  ShearSummary summary() const;
  // Preparation results.
  double achieved_void_ratio() const { return progress_.compacted_void_ratio; }
  double achieved_relative_density() const;
  std::int64_t phase_step(ShearPhase p) const { return progress_.phase_start_step[static_cast<int>(p)]; }

  // The protocol's own state, for checkpoints (the World's State is saved
  // separately). Restoring both reproduces the run bit for bit.
  std::vector<std::uint8_t> save_progress() const;
  void load_progress(std::span<const std::uint8_t> bytes);

  // Walls by role.
  enum WallRole { Floor = 0, LowerXm, LowerXp, LowerYm, LowerYp, UpperXm, UpperXp, UpperYm, UpperYp, Cap, WallCount };

 private:
  struct Progress {
    ShearPhase phase = ShearPhase::Deposit;
    std::int32_t calm_checks = 0;       // consecutive checks meeting the rest criteria
    double compacted_void_ratio = 0;
    double cap_z_at_shear = 0;
    double upper_x_at_shear = 0;
    double next_sample_strain = 0;
    double servo_integral = 0;          // Pa, the servo's integral term
    std::int32_t window_steps = 0;      // steps summed in force_sum
    std::vector<Vec3> force_sum;        // N, per grain, over the current calm run
    std::array<std::int64_t, 5> phase_start_step{};
    std::vector<std::vector<double>> rows;
    std::vector<BodyState> reference;  // grains at the start of shear
  };

  void build_walls();
  void enter(ShearPhase p);
  void servo(World& w, double dt);
  // Kinetic energy small against the elastic energy and the stress within
  // tolerance; strict (consolidation): the configured tolerance and the
  // averaged unbalanced-force ratio too. The compaction accepts 5 % and skips
  // the ratio: the consolidation that follows settles both.
  bool at_rest(bool strict) const;
  // force over the mean magnitude of the contact forces (1 with no contacts).
  double per_mean_contact_force(double force) const;
  void record_sample();
  double box_area() const { return spec_.box.length * spec_.box.width; }
  Index wall(WallRole r) const { return static_cast<Index>(r); }

  DirectShearSpec spec_;
  World world_;
  Progress progress_;
  double dt_ = 0;
  double shear_speed_ = 0;
  double solid_volume_ = 0;
  double mean_diameter_ = 0;
  double mean_mass_ = 0;
  double fill_top_ = 0;
  Index grain_material_ = 0;
  Index wall_material_ = 1;
  double cap_speed_limit_ = 0;
  std::vector<std::string> observer_columns_;
  SampleObserver observer_;
};

}  // namespace grainlab
