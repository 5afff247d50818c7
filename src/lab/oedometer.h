// The virtual oedometer: one-dimensional compression (ASTM D2435 in spirit)
// of a specimen in a rigid square ring, frictionless or with
// material.wall_friction, under a schedule of cap stresses.
//
// Box and preparation (lab/closed_box_test.h): the direct shear box with its
// gap closed, a rigid ring of L x W, and the specimen preparation's deposit,
// compact and consolidate phases (lab/preparation.h) under
// consolidation.normal_stress.
//
// Loading (phase "load"): the cap's servo (lab/stress_servo.h, integral
// reset at each stage) holds each stress of oedometer.stresses in turn until
// the specimen is at rest by the consolidation's criteria: the cap stress
// within consolidation.tolerance of the stage's, the kinetic energy below
// 1e-2 of the contacts' elastic energy for kCalmChecks checks in a row, and
// the unbalanced-force ratio of the grains' resultants averaged over that
// calm run below consolidation.max_unbalanced. A stress below the one
// before unloads. The servo moves the cap no faster than the constant-rate
// speed below (a stage is a quasi-static load, then a hold: at the
// preparation's speed limit, about 1000 times faster, each stage was a
// sudden load or release that rearranged the grains, K0 0.68 against 0.61
// at 200 kPa in tests/lab/oedometer_test.cpp's specimen). One series row is
// recorded at rest at the end of every stage, the consolidated state first
// (stage 0).
//
// Constant rate of strain (oedometer.loading = "constant-rate", ASTM D4186
// in spirit): the cap moves at the constant speed v = I H_0 / (d
// sqrt(rho S / sigma_0)) (I = numerics.inertial_number, sigma_0 the
// consolidation stress: I falls as the stress grows), downwards until the
// cap stress reaches the stage's stress, upwards (unloading) until it falls
// to it; no servo, no rest. A row every time sigma_v has changed by a factor
// 10^(1/50) since the last (50 rows per decade of stress) and one when each
// stage's stress is reached; the column "stage" is the stage being
// approached, so each stage's last row is where its stress was reached.
//
// Measured (SI, compression positive):
//   sigma_v  = N_cap / (L W), the cap's stress (the servo's);
//   sigma_f  = N_floor / (L W): below sigma_v by the side walls' friction;
//   sigma_h  = mean of the four side walls' normal stresses, each wall's
//              normal force over its area in contact, side x H (H the cap height);
//   K0       = sigma_h / sigma_v;
//   eps_v    = (H_0 - H) / H_0, H_0 the height at stage 0;
//   e        = (L W H - V_s) / V_s;
//   M        = (sigma_v,i - sigma_v,i-1) / (eps_v,i - eps_v,i-1), the
//              constrained (oedometric) modulus of stage i's increment.
// Summary (oedometer_summary), over each stage's last row (with stages, the
// one row of each stage; at a constant rate, where the stress was reached),
// M recomputed between those rows:
//   Cc = -(e_i - e_{i-1}) / log10(sigma_i / sigma_{i-1}) of the last loading
//        increment before the first unloading (the highest stresses: for
//        sands the e-log sigma line steepens with stress, and the last
//        increment is the nearest to the normal compression line);
//   Cs = -(e_min_stress - e_max) / log10(sigma_min / sigma_max) over the
//        whole unloading branch after the largest stress (NaN without one);
//   K0 and M at the largest stress; the power n of M ~ sigma^n fitted by
//   least squares to log M against the log of each loading increment's
//   mean stress, the first increment left out (it starts from the
//   preparation's stress state, K0 0.73-0.90 after consolidation, and
//   rearranges it; measured, it lowers n from 0.34 to 0.22-0.25)
//   (effective-medium theory of Hertz spheres with a fixed contact network:
//   n = 1/3; contacts that form under load raise it).
#pragma once

#include "lab/closed_box_test.h"
#include "lab/rest_criteria.h"
#include "lab/spec_keys.h"
#include "lab/stress_servo.h"

#include <cstdint>
#include <string>
#include <vector>

namespace grainlab {

// The oedometer's own settings (config table [oedometer]): after
// consolidation under consolidation.normal_stress, the cap goes through the
// schedule of stresses in order (a stress below the one before unloads):
// with loading "stages" its servo holds each stress until the specimen is at
// rest; with "constant-rate" it moves at a constant speed (from
// numerics.inertial_number) until the cap stress reaches each stress, and
// reverses to unload.
struct OedometerSpec {
  std::vector<double> stresses = {200e3, 400e3, 800e3, 400e3, 200e3, 100e3};  // Pa, in order
  std::string loading = "stages";  // "stages" | "constant-rate"
};

enum class OedometerPhase : std::int32_t { Prepare = 0, Load = 1, Done = 2 };

// Column names (with units) of the series: one row per stage at rest.
const std::vector<std::string>& oedometer_series_columns();
// Columns of oedometer_series_columns(), by name (rows[i][OedometerColumn::K0]).
struct OedometerColumn {
  enum : int {
    Time, Stage, Target, Vertical, FloorStress, Lateral, K0, Strain, Height, VoidRatio, Modulus, Coordination,
    KineticEnergy, UnbalancedForce
  };
};

// What the oedometer's stage rows give (see the top of this file).
struct OedometerSummary {
  double compression_index = 0;    // Cc
  double swelling_index = 0;       // Cs (NaN without unloading)
  double max_stress = 0;           // Pa, the largest stage stress reached
  double k0_at_max_stress = 0;
  double modulus_at_max_stress = 0;  // Pa, M of the increment that reached it
  double modulus_stress_exponent = 0;  // n of M ~ sigma^n over the loading increments (NaN: fewer than 2)
  double final_void_ratio = 0;
};
// From the series rows (oedometer_series_columns() order); zeros before two rows.
OedometerSummary summarise_oedometer(const std::vector<std::vector<double>>& rows);

class OedometerTest final : public ClosedBoxTest {
 public:
  // Builds the preparation (the direct shear box with its gap closed).
  explicit OedometerTest(const LabSpec& spec);
  // Goes on from a preparation of preparation_spec(spec) (lab/closed_box_test.h).
  OedometerTest(const LabSpec& spec, std::unique_ptr<SpecimenPreparation> preparation);
  // Its config table [oedometer] (lab/spec_keys.h).
  static LabTestKeys keys();

  // LabTest.
  bool advance(int max_steps) override;
  int phase_index() const override;
  std::string phase_name() const override;
  bool loading() const override { return p_.phase == OedometerPhase::Load; }
  bool done() const override { return p_.phase == OedometerPhase::Done; }
  std::int64_t loading_start_step() const override { return p_.load_start_step; }
  double progress() const override;
  double final_progress() const override { return 1; }
  // Constant rate of strain instead of stages held to rest.
  bool constant_rate() const { return constant_rate_; }
  double cap_speed() const { return cap_speed_; }       // m/s at a constant rate (0 before loading)
  std::string progress_label() const override { return "fraction of the load stages done"; }
  std::string status_line() const override;
  std::string phase_note() const override;
  std::string result_line() const override;
  const std::vector<std::vector<double>>& series() const override { return p_.rows; }
  const std::vector<BodyState>& reference() const override { return p_.reference; }
  std::vector<SummaryValue> summary() const override;
  double specimen_volume() const override;
  double boundary_stress() const override { return vertical_stress(); }
  std::optional<BandGeometry> band_geometry() const override;
  std::vector<std::uint8_t> save() const override;
  void load(std::span<const std::uint8_t> bytes) override;

  // Oedometer measurements (definitions above).
  OedometerPhase phase() const { return p_.phase; }
  int stage() const { return p_.stage; }               // the stage held now (0: consolidation)
  int stages() const { return static_cast<int>(spec_.settings<OedometerSpec>().stresses.size()); }
  double stage_stress(int stage) const;                // Pa, stage 0: consolidation.normal_stress
  double vertical_stress() const;                      // Pa, on the cap
  double floor_stress() const;                         // Pa, on the floor
  double lateral_stress() const;                       // Pa, mean of the four side walls
  double vertical_strain() const;                      // since stage 0 (0 before)
  double void_ratio() const { return prep_->void_ratio(); }

 private:
  struct Progress {
    OedometerPhase phase = OedometerPhase::Prepare;
    std::int32_t stage = 0;
    RestRun rest;
    double height_at_load = 0;      // m, H_0
    double last_row_stress = 0;     // Pa, sigma_v of the last row (constant rate)
    std::int64_t load_start_step = 0;
    std::int64_t stage_start_step = 0;
    std::vector<std::vector<double>> rows;
    std::vector<BodyState> reference;  // grains at stage 0
  };

  const std::vector<std::string>& own_columns() const override { return oedometer_series_columns(); }
  void start_loading();
  void start_stage(int stage);
  bool stage_at_rest();
  bool stage_reached() const;  // constant rate: the cap stress has reached the stage's
  StressServo stage_servo(int stage) const;  // stages: holds the stage's stress
  void set_cap_speed();        // constant rate: cap_speed_ from the inertial number
  bool advance_constant_rate(int max_steps);
  void record_row();
  double area() const { return spec_.box.length * spec_.box.width; }
  double cap_height() const;

  Progress p_;
  StressServo servo_{0, 0, 0, 0};  // set at each stage
  double cap_speed_ = 0;            // m/s, constant rate
  bool constant_rate_ = false;      // oedometer.loading == "constant-rate" (read every step)
};

}  // namespace grainlab
