// Displacement profile and shear band (method in shear_band.h).
#include "analysis/shear_band.h"

#include "analysis/preconditions.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace grainlab::analysis {

namespace {

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t h = v.size() / 2;
  return v.size() % 2 ? v[h] : 0.5 * (v[h - 1] + v[h]);
}

}  // namespace

DisplacementProfile displacement_profile(const State& now, const State& ref, const ProfileSpec& spec) {
  check_same_bodies(now, ref, "displacement_profile");
  if (spec.layers < 1)
    throw std::invalid_argument(fmt::format("displacement_profile: {} layers; need at least 1", spec.layers));
  if (!(spec.shear_direction.norm() > 0))
    throw std::invalid_argument("displacement_profile: the shear direction is zero");
  const Vec3 e = spec.shear_direction.normalized();
  const std::size_t n = ref.bodies.size();

  DisplacementProfile p;
  p.z_min = spec.z_min;
  p.z_max = spec.z_max;
  if (!(spec.z_min < spec.z_max)) {
    p.z_min = std::numeric_limits<double>::infinity();
    p.z_max = -p.z_min;
    for (const BodyState& b : ref.bodies) {
      p.z_min = std::min(p.z_min, b.x.z());
      p.z_max = std::max(p.z_max, b.x.z());
    }
    if (n == 0) p.z_min = p.z_max = 0;
  }
  const std::size_t layers = static_cast<std::size_t>(spec.layers);
  const double dz = (p.z_max - p.z_min) / static_cast<double>(layers);
  std::vector<double> sum(layers, 0.0);
  p.count.assign(layers, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const double z = ref.bodies[i].x.z();
    if (z < p.z_min || z > p.z_max) continue;
    // The top edge belongs to the last layer; a zero-height range to the first.
    const std::size_t k = dz > 0 ? std::min(layers - 1, static_cast<std::size_t>((z - p.z_min) / dz)) : 0;
    sum[k] += (now.bodies[i].x - ref.bodies[i].x).dot(e);
    ++p.count[k];
  }
  p.z.resize(layers);
  p.u.resize(layers);
  for (std::size_t k = 0; k < layers; ++k) {
    p.z[k] = p.z_min + (static_cast<double>(k) + 0.5) * dz;
    p.u[k] = p.count[k] ? sum[k] / p.count[k] : std::numeric_limits<double>::quiet_NaN();
  }
  return p;
}

ShearBand find_shear_band(const DisplacementProfile& profile, const BandSpec& spec) {
  if (!(spec.lower > 0 && spec.lower < 0.5 && spec.upper > 0.5 && spec.upper < 1))
    throw std::invalid_argument(fmt::format(
        "find_shear_band: limits {} and {} must satisfy 0 < lower < 1/2 < upper < 1", spec.lower, spec.upper));
  // The non-empty layers, bottom to top.
  std::vector<double> z, u;
  for (std::size_t k = 0; k < profile.u.size(); ++k) {
    if (k < profile.count.size() && profile.count[k] > 0 && std::isfinite(profile.u[k])) {
      z.push_back(profile.z[k]);
      u.push_back(profile.u[k]);
    }
  }
  ShearBand band;
  const std::size_t n = z.size();
  if (n < 2) return band;
  const std::size_t k = std::clamp<std::size_t>(
      static_cast<std::size_t>(std::lround(spec.plateau_fraction * static_cast<double>(n))), 1, n / 2);
  band.u_bottom = median(std::vector<double>(u.begin(), u.begin() + static_cast<std::ptrdiff_t>(k)));
  band.u_top = median(std::vector<double>(u.end() - static_cast<std::ptrdiff_t>(k), u.end()));
  const double jump = band.u_top - band.u_bottom;
  if (!(std::abs(jump) > spec.min_jump) || jump == 0) return band;

  std::vector<double> U(n);
  for (std::size_t i = 0; i < n; ++i) U[i] = (u[i] - band.u_bottom) / jump;
  // z where U = level on the segment (i, i+1).
  const auto cross = [&](std::size_t i, double level) {
    return z[i] + (level - U[i]) / (U[i + 1] - U[i]) * (z[i + 1] - z[i]);
  };
  // 1. The first upward crossing of 1/2.
  std::size_t m = n;
  for (std::size_t i = 0; i + 1 < n; ++i) {
    if (U[i] < 0.5 && U[i + 1] >= 0.5) {
      m = i;
      break;
    }
  }
  if (m == n) return band;
  band.z_mid = cross(m, 0.5);
  // 2. Down from the middle to the first layer at or below `lower`.
  band.z_low = z.front();
  for (std::size_t j = m + 1; j-- > 0;) {
    if (U[j] <= spec.lower) {
      band.z_low = cross(j, spec.lower);
      break;
    }
  }
  // 3. Up from the middle to the first layer at or above `upper`.
  band.z_high = z.back();
  for (std::size_t j = m + 1; j < n; ++j) {
    if (U[j] >= spec.upper) {
      band.z_high = cross(j - 1, spec.upper);
      break;
    }
  }
  band.found = true;
  return band;
}

GrainMask grains_in_band(const State& s, const ShearBand& band) {
  GrainMask mask(s.bodies.size(), 0);
  if (!band.found) return mask;
  for (std::size_t i = 0; i < s.bodies.size(); ++i) {
    const double z = s.bodies[i].x.z();
    mask[i] = z >= band.z_low && z <= band.z_high;
  }
  return mask;
}

}  // namespace grainlab::analysis
