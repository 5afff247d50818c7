// Peak and final values of a direct shear series (paper Eqs. 18-19): the peak
// friction angle phi = atan(F/N) with its stress ratio and strain; the dilation
// angle psi = atan(d(d_v)/d(d_h)) by central differences over +-2 samples
// (single intervals are noisy) and its peak; the means of phi and psi over the
// last 10 % of strain; the final void ratio.
#pragma once

#include <vector>

namespace grainlab {

// Columns of shear_series_columns() (lab/direct_shear.h), by name (rows[i][ShearColumn::StressRatio]).
struct ShearColumn {
  enum : int {
    Time, Strain, HorizontalDisplacement, VerticalDisplacement, ShearForce, NormalForce, NormalStress,
    StressRatio, FrictionAngle, VoidRatio, Coordination, KineticEnergy, UnbalancedForce, InertialNumber
  };
};

// Peak and final values of a run.
struct ShearSummary {
  double peak_friction_angle_deg = 0, strain_at_peak_friction = 0;
  double peak_dilation_angle_deg = 0, strain_at_peak_dilation = 0;
  double peak_stress_ratio = 0;
  double final_friction_angle_deg = 0, final_dilation_angle_deg = 0;  // mean over the last 10 % of strain
  double final_void_ratio = 0;
};

// The summary of a series whose first columns are shear_series_columns()
// (zeros with fewer than two rows).
ShearSummary summarise_shear(const std::vector<std::vector<double>>& rows);

}  // namespace grainlab
