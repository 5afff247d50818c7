// The virtual drained triaxial test (compression) of a cuboid specimen
// between rigid walls: the four side walls and the cap are each driven by a
// stress servo (lab/stress_servo.h), the floor is fixed.
//
// Box and preparation (lab/closed_box_test.h): the direct shear box with its
// gap closed, prepared by the specimen preparation's deposit, compact and
// consolidate phases (lab/preparation.h) under the cap at consolidation.normal_stress = sigma_3. Each side of the ring is its two
// slabs moving as one; they are kShearBoxSlab thick and overlap the
// neighbouring sides by that much, so a side may move outwards by up to that
// before a corner opens (the run stops with a message if one would).
//
// Phases after the preparation:
//   isotropic  the cap and the four sides are servo-held at sigma_3 until the
//              specimen is at rest (the consolidation's criteria, all five
//              stresses within consolidation.tolerance);
//   shear      the cap moves down at a constant speed v from the inertial
//              number, I = (v / H_0) d sqrt(rho S / sigma_3), while the four
//              sides hold sigma_3; a sample every output.strain_interval of
//              axial strain up to triaxial.final_strain.
//
// Measured (compression positive; L_x, L_y the distances between the sides'
// inner faces, H the cap height, V = L_x L_y H, index 0 at the start of
// shear):
//   sigma_1 = N_cap / (L_x L_y); sigma_3 = mean of the four sides' stresses
//   (normal force / (width x H)); q = sigma_1 - sigma_3, p' = (sigma_1 + 2
//   sigma_3) / 3, eta = q / p';
//   eps_a = (H_0 - H) / H_0, eps_v = (V_0 - V) / V_0, e = (V - V_s) / V_s;
//   side_stress_error: the largest over the four sides of |mean stress over
//   the steps since the last sample / sigma_3 - 1| (the servo's hold, as a
//   load cell's filtered reading: a small specimen's force chains make the
//   instantaneous side stress swing by a few per cent).
//
// The side servos' gain (kSideAlpha = 0.15, the cap's and the preparation's
// 0.05): a side wall must follow the specimen's dilation and its force
// chains' collapses, and its stress is its own contacts' (no column of
// grains between the wall and what it measures). Measured on the default
// box of glass beads at 50 kPa, I = 9e-4, to 6 % axial strain (the worst
// sample's side stress error; the mean): alpha 0.05: 4.0 %, 0.70 %; 0.10:
// 0.95 %, 0.21 %; 0.15: 0.43 %, 0.08 %; 0.20: 0.25 %, 0.06 %, with the same
// q/p' curve (peak 0.819, 0.818); 0.30 and above oscillate in the isotropic
// phase (likely as the control bandwidth alpha / dt nears the frequency of
// the grains against the wall, below 0.8 / dt at the critical step's fraction
// 0.4), so 0.15 keeps a factor 2 to that. Sub-angular grains at 100 kPa with 0.20: 0.33 %
// at worst.
// Summary (triaxial_summary): the friction angle from eta, sin phi = 3 eta /
// (6 + eta), at the peak of eta averaged over 1 % of axial strain (the
// samples within 0.5 % either side: the maximum of the raw samples would be
// the largest swing of a small specimen's noise) and at the critical state
// (eta averaged over the last fifth of the strain); the peak dilatancy angle, sin psi =
// -r / (2 - r) with r = d eps_v / d eps_a over 1 % of axial strain (Vermeer
// and de Borst's triaxial form; dilation makes r negative); the dilatancy
// angle over that last fifth, from the least-squares slope r of eps_v on
// eps_a there: a critical state has none, so a specimen still dilating at
// the end has not reached one and its "critical" eta is an upper bound
// (reported beside it, not decided by a threshold); the secant
// modulus E50 = (q_peak / 2) / eps_a where q first reaches half its peak.
//
// Rigid walls against a membrane: a lab specimen's flexible membrane lets
// the specimen bulge and a shear band cross it freely; rigid plane walls
// keep the sides flat, so a band is forced to reflect at the walls and the
// specimen deforms as a cuboid. Peak and critical-state friction angles
// are little changed for specimens many grains wide; the post-peak
// softening and the strain at which the band forms are.
#pragma once

#include "lab/closed_box_test.h"
#include "lab/rest_criteria.h"
#include "lab/spec_keys.h"
#include "lab/stress_servo.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace grainlab {

// The triaxial test's own settings (config table [triaxial]): isotropic
// consolidation at consolidation.normal_stress (sigma_3), then axial
// compression at the inertial number's speed to this axial strain.
struct TriaxialSpec {
  double final_strain = 0.15;  // axial strain (H_0 - H) / H_0 at which the test ends
};

enum class TriaxialPhase : std::int32_t { Prepare = 0, Isotropic = 1, Shear = 2, Done = 3 };

// Column names (with units) of the series recorded during shear.
const std::vector<std::string>& triaxial_series_columns();
// Columns of triaxial_series_columns(), by name (rows[i][TriaxialColumn::Ratio]).
struct TriaxialColumn {
  enum : int {
    Time, AxialStrain, VolumetricStrain, Sigma1, Sigma3, Deviator, Mean, Ratio, SideError, VoidRatio, Coordination,
    KineticEnergy, UnbalancedForce, InertialNumber
  };
};

// What the triaxial rows give (definitions above).
struct TriaxialSummary {
  double peak_stress_ratio = 0;       // eta = q / p' at its peak
  double strain_at_peak = 0;          // eps_a there
  double peak_friction_angle_deg = 0;
  double critical_stress_ratio = 0;   // eta over the last fifth of the strain
  double critical_friction_angle_deg = 0;
  double critical_dilatancy_angle_deg = 0;  // over the same last fifth: 0 at a critical state
  double peak_dilatancy_angle_deg = 0;
  double e50_Pa = 0;                  // secant modulus at half the peak deviator
  double final_void_ratio = 0;
};
// From the series rows (triaxial_series_columns() order).
TriaxialSummary summarise_triaxial(const std::vector<std::vector<double>>& rows);

class TriaxialTest final : public ClosedBoxTest {
 public:
  static constexpr double kSideAlpha = 0.15;  // the side servos' gain (above)

  explicit TriaxialTest(const LabSpec& spec);
  // Goes on from a preparation of preparation_spec(spec) (lab/closed_box_test.h).
  TriaxialTest(const LabSpec& spec, std::unique_ptr<SpecimenPreparation> preparation);
  // Its config table [triaxial] (lab/spec_keys.h).
  static LabTestKeys keys();

  // LabTest.
  bool advance(int max_steps) override;
  int phase_index() const override;
  std::string phase_name() const override;
  bool loading() const override { return p_.phase == TriaxialPhase::Shear; }
  bool done() const override { return p_.phase == TriaxialPhase::Done; }
  std::int64_t loading_start_step() const override { return p_.shear_start_step; }
  double progress() const override { return axial_strain(); }
  double final_progress() const override { return spec_.settings<TriaxialSpec>().final_strain; }
  std::string progress_label() const override { return "axial strain"; }
  std::string status_line() const override;
  std::string phase_note() const override;
  std::string result_line() const override;
  const std::vector<std::vector<double>>& series() const override { return p_.rows; }
  const std::vector<BodyState>& reference() const override { return p_.reference; }
  std::vector<SummaryValue> summary() const override;
  double specimen_volume() const override { return length(0) * length(1) * cap_height(); }
  double boundary_stress() const override { return cell_pressure(); }
  std::optional<BandGeometry> band_geometry() const override;
  std::vector<std::uint8_t> save() const override;
  void load(std::span<const std::uint8_t> bytes) override;

  // Triaxial measurements (definitions above).
  TriaxialPhase phase() const { return p_.phase; }
  double axial_speed() const { return axial_speed_; }   // m/s of the cap in shear
  double length(int axis) const;                       // m, between the inner faces of the sides (axis 0: x, 1: y)
  double axial_stress() const;                         // Pa, sigma_1 on the cap
  double side_stress(int side) const;                  // Pa, side 0..3: -x, +x, -y, +y
  double cell_pressure() const;                        // Pa, sigma_3: the mean of the four sides
  double axial_strain() const;                         // eps_a since the start of shear (0 before)
  double volumetric_strain() const;                    // eps_v since the start of shear (0 before)
  double void_ratio() const;

 private:
  struct Progress {
    TriaxialPhase phase = TriaxialPhase::Prepare;
    RestRun rest;
    double height_at_shear = 0, volume_at_shear = 0;
    double next_sample_strain = 0;
    std::array<double, 4> side_stress_sum{};  // Pa x steps since the last sample (shear)
    std::int32_t steps_since_sample = 0;
    std::int64_t phase_start_step = 0;
    std::int64_t shear_start_step = 0;
    std::vector<std::vector<double>> rows;
    std::vector<BodyState> reference;  // grains at the start of shear
  };

  const std::vector<std::string>& own_columns() const override { return triaxial_series_columns(); }
  void enter(TriaxialPhase p);
  bool isotropic_at_rest();
  void check_corners() const;
  void record_sample();
  double cap_height() const;
  double side_area(int side) const;

  Progress p_;
  StressServo cap_servo_{0, 0, 0, 0};
  std::array<StressServo, 4> side_servos_{StressServo{0, 0, 0, 0}, StressServo{0, 0, 0, 0},
                                          StressServo{0, 0, 0, 0}, StressServo{0, 0, 0, 0}};
  double axial_speed_ = 0;
};

}  // namespace grainlab
