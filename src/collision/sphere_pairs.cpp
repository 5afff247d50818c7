// Sphere-sphere contact geometry, four pairs at a time (see sphere_pairs.h).
#include "collision/sphere_pairs.h"

#include <cmath>
#include <cstring>

namespace grainlab {

namespace {

using Lanes = double __attribute__((vector_size(32)));

Lanes load(const double* p) {  // unaligned, no aliasing assumed
  Lanes v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

// Four spheres (x, y, z, r each) into lanes of x, of y, of z and of r
// (__builtin_shufflevector: GCC 12 and clang alike; indices into the two
// vectors side by side).
void transpose(const SphereXYZR s[4], Lanes& x, Lanes& y, Lanes& z, Lanes& r) {
  const Lanes s0 = load(s[0]), s1 = load(s[1]), s2 = load(s[2]), s3 = load(s[3]);
  const Lanes xz01 = __builtin_shufflevector(s0, s1, 0, 4, 2, 6), yr01 = __builtin_shufflevector(s0, s1, 1, 5, 3, 7);
  const Lanes xz23 = __builtin_shufflevector(s2, s3, 0, 4, 2, 6), yr23 = __builtin_shufflevector(s2, s3, 1, 5, 3, 7);
  x = __builtin_shufflevector(xz01, xz23, 0, 1, 4, 5);
  z = __builtin_shufflevector(xz01, xz23, 2, 3, 6, 7);
  y = __builtin_shufflevector(yr01, yr23, 0, 1, 4, 5);
  r = __builtin_shufflevector(yr01, yr23, 2, 3, 6, 7);
}

void store(double* p, Lanes v) { std::memcpy(p, &v, sizeof v); }

Lanes root(Lanes x) {
#if defined(__AVX__)
  return __builtin_ia32_sqrtpd256(x);
#else
  Lanes r;
  for (int l = 0; l < 4; ++l) r[l] = std::sqrt(x[l]);
  return r;
#endif
}

}  // namespace

void sphere_pairs(const SphereXYZR a[4], const SphereXYZR b[4], SpherePairsOut& out) {
  Lanes ax, ay, az, ar, bx, by, bz, br;
  transpose(a, ax, ay, az, ar);
  transpose(b, bx, by, bz, br);
  const Lanes dx = bx - ax, dy = by - ay, dz = bz - az;
  const Lanes dist = root(dx * dx + dy * dy + dz * dz);
  const auto apart = dist > 1e-300;  // else coincident centres
  const Lanes zero{}, one = zero + 1.0;
  const Lanes nx = apart ? dx / dist : zero, ny = apart ? dy / dist : zero, nz = apart ? dz / dist : one;
  const Lanes half_gap = 0.5 * (ar - br);
  store(out.depth, (ar + br) - dist);
  store(out.nx, nx);
  store(out.ny, ny);
  store(out.nz, nz);
  store(out.px, 0.5 * (ax + bx) + half_gap * nx);
  store(out.py, 0.5 * (ay + by) + half_gap * ny);
  store(out.pz, 0.5 * (az + bz) + half_gap * nz);
}

}  // namespace grainlab
