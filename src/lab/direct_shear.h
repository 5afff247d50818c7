// The virtual direct shear test (ASTM D3080 in spirit; paper sections 3-5),
// built on the lab kit: the box of lab/shear_box.h, the specimen of
// lab/specimen.h, the servo of lab/stress_servo.h, the rest criteria of
// lab/rest_criteria.h. The shear plane is at z = H/2 for a specimen of
// height H; the upper half moves along +x, the cap rides with it in x and is
// servo-controlled in z.
//
// Protocol (phases): the specimen's preparation (lab/preparation.h: deposit,
// compact, consolidate, in this box with its gap closed), then
//   Shear        the gap opens, the upper half moves at constant speed to the
//                final strain, the cap's servo holding the normal stress. A
//                sample is recorded every output.strain_interval of shear strain.
//
// Measured (DESIGN.md "Walls and the direct shear box"): shear force F on the
// upper half (minus the x force the grains put on its slabs and the cap),
// normal force N on the cap, d_h, d_v, shear strain d_h / L, void ratio
// e = (L W z_cap - V_s) / V_s, coordination number 2 N_c / N_p (grain-grain
// contacts), kinetic energy, unbalanced-force ratio (mean |resultant| per grain
// over mean |contact force|) and the inertial number I = (v / H) d sqrt(rho S / sigma).
#pragma once

#include "lab/lab_spec.h"
#include "lab/prepared_test.h"
#include "lab/shear_summary.h"
#include "lab/spec_keys.h"

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace grainlab {

// The direct shear's own settings (config table [shear]).
struct ShearSpec {
  double speed = 0;                 // m/s of the upper half; 0 = from numerics.inertial_number
  double final_strain = 0.10;       // d_h / L
};

// The preparation's phases, then the test's own.
enum class ShearPhase : std::int32_t { Deposit = 0, Compact = 1, Consolidate = 2, Shear = 3, Done = 4 };
const char* shear_phase_name(ShearPhase p);

// Column names (with units) of the series recorded during shear.
const std::vector<std::string>& shear_series_columns();


class DirectShearTest final : public PreparedTest {
 public:
  // Builds the preparation of `spec`.
  explicit DirectShearTest(const LabSpec& spec);
  // Its config table [shear] (lab/spec_keys.h).
  static LabTestKeys keys();
  // Goes on from `preparation` (of this spec, prepared or not yet: the
  // preparation search's trial that hit the target).
  DirectShearTest(const LabSpec& spec, std::unique_ptr<SpecimenPreparation> preparation);

  // LabTest.
  bool advance(int max_steps) override;
  int phase_index() const override { return static_cast<int>(phase()); }
  std::string phase_name() const override { return shear_phase_name(phase()); }
  bool loading() const override { return phase() == ShearPhase::Shear; }
  bool done() const override { return phase() == ShearPhase::Done; }
  std::int64_t loading_start_step() const override { return phase_step(ShearPhase::Shear); }
  double progress() const override { return shear_strain(); }
  double final_progress() const override { return spec_.settings<ShearSpec>().final_strain; }
  std::string progress_label() const override { return "shear strain"; }
  std::string status_line() const override;
  std::string phase_note() const override;
  std::string result_line() const override;
  const std::vector<std::vector<double>>& series() const override { return p_.rows; }
  const std::vector<BodyState>& reference() const override { return p_.reference; }
  std::vector<SummaryValue> summary() const override;
  std::optional<BandGeometry> band_geometry() const override;
  std::vector<std::uint8_t> save() const override;
  void load(std::span<const std::uint8_t> bytes) override;

  // Direct shear measurements and settings.
  ShearPhase phase() const {
    return prep_->prepared() ? p_.phase : static_cast<ShearPhase>(static_cast<int>(prep_->phase()));
  }
  std::int64_t phase_step(ShearPhase p) const;
  double shear_speed() const { return shear_speed_; }
  double solid_volume() const { return prep_->solid_volume(); }    // m^3
  double mean_diameter() const { return prep_->mean_diameter(); }  // m, volume-equivalent
  double shear_strain() const;
  double normal_stress() const { return prep_->normal_stress(); }  // Pa, on the cap
  double shear_force() const;    // N, on the upper half
  double normal_force() const { return prep_->normal_force(); }    // N, on the cap
  double void_ratio() const { return prep_->void_ratio(); }
  double coordination_number() const { return prep_->coordination_number(); }
  double inertial_number() const;
  double cap_displacement() const;  // m, since the start of shear (up is positive)
  double servo_integral() const { return prep_->servo_integral(); }  // Pa
  ShearSummary shear_summary() const { return summarise_shear(p_.rows); }
  // The specimen's void ratio and Dr (lab/preparation.h).
  double achieved_void_ratio() const { return prep_->achieved_void_ratio(); }
  double achieved_bulk_void_ratio() const { return prep_->achieved_bulk_void_ratio(); }
  double achieved_relative_density() const { return prep_->achieved_relative_density(); }
  double achieved_own_relative_density() const { return prep_->achieved_own_relative_density(); }
  double achieved_lab_relative_density() const { return prep_->achieved_lab_relative_density(); }
  double bulk_void_ratio() const { return prep_->bulk_void_ratio(); }

 private:
  struct Progress {
    ShearPhase phase = ShearPhase::Shear;  // once prepared: Shear or Done
    double cap_z_at_shear = 0;
    double upper_x_at_shear = 0;
    double next_sample_strain = 0;
    std::int64_t shear_start_step = 0, done_step = 0;
    std::vector<std::vector<double>> rows;
    std::vector<BodyState> reference;  // grains at the start of shear
  };

  const std::vector<std::string>& own_columns() const override { return shear_series_columns(); }
  void start_shear();
  void finish();
  void record_sample();

  Progress p_;
  double shear_speed_ = 0;
};

}  // namespace grainlab
