// A tessellated sphere (the hull of n points of a Fibonacci lattice on a
// sphere of radius R: 2n - 4 faces) pressed on a plane, or on another one,
// follows Hertz's force-overlap curve F = (4/3) E* sqrt(R*) delta^{3/2} more
// closely as its faces grow (collision/soft_depth.h: for vertices evenly
// spread over the cap the soft depth D equals the overlap delta and the gain
// is 1). delta is the overlap of the spheres the vertices lie on, R* = R (plane)
// or R/2 (two spheres); the engine's force is read after one step from rest.
#include "core/rng.h"
#include "dynamics/laws/registry.h"
#include "dynamics/world.h"
#include "geometry/convex_hull.h"
#include "geometry/mass_properties.h"
#include "geometry/rounded_hull.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <numbers>

using namespace grainlab;

namespace {

constexpr double kR = 1e-3;  // sphere radius (m)

Material elastic_glass() {
  Material m;
  m.density = 2500;
  m.youngs_modulus = 1e8;
  m.poisson_ratio = 0.25;
  m.restitution = 1.0;  // no damping: the force is the elastic one
  m.friction = 0;
  return m;
}

struct Tessellated {
  TriMesh mesh;
  Vec3 centre_local;  // the circumsphere's centre in the shape's principal frame
  double radius;      // volume-equivalent radius, the engine's Hertz radius (m)
};

Tessellated tessellated_sphere(int points) {
  std::vector<Vec3> p = fibonacci_directions(points);
  for (Vec3& v : p) v *= kR;
  Tessellated t;
  t.mesh = convex_hull(p).mesh();
  const MassProperties mp = mass_properties(t.mesh);
  t.centre_local = mp.principal_axes.transpose() * (-mp.centroid);  // Model's p_local = A^T (p - c)
  t.radius = std::cbrt(3 * mp.volume / (4 * std::numbers::pi));
  return t;
}

struct HertzError {
  double mean;   // largest over the overlaps of |mean over orientations of F/F_Hertz - 1|
  double worst;  // largest |F/F_Hertz - 1| over overlaps and orientations
};

// F / F_Hertz at overlaps of 1, 2 and 4 % of R in 6 random orientations,
// against a plane (two = false) or a second sphere. Where a vertex lies, the
// tessellation is exact; between vertices its faces lie inside the sphere, by
// 3 rho^2/(8R) on average over a triangle of circumradius rho (1.8e-4 R at
// 20000 faces): two tessellated spheres touch vertex on face, and their
// overlap is short of the spheres' by about that.
// (Below the tessellation's sag, about s^2/(8R) for a vertex spacing s, the
// polytope may not touch at all: 0.015 R at 200 faces, 1.5e-4 R at 20000.)
HertzError hertz_error(int points, bool two) {
  const Tessellated t = tessellated_sphere(points);
  const Material mat = elastic_glass();
  const double e_star = 1.0 / (2 * (1 - mat.poisson_ratio * mat.poisson_ratio) / mat.youngs_modulus);
  const double r_star = two ? 0.5 * t.radius : t.radius;
  World w;
  w.model.law = contact_law<HertzMaterialLaw>();
  w.model.gravity = Vec3::Zero();
  const Index m = w.model.add_material(mat);
  const Index s = w.model.add_mesh_shape(t.mesh, "sphere");
  if (two) {
    w.add_body(s, m, 1.0, Vec3::Zero(), Quat::Identity());
    w.add_body(s, m, 1.0, Vec3(0, 0, 3 * kR), Quat::Identity());
  } else {
    w.add_plane(Vec3::Zero(), Vec3::UnitZ(), m, "floor");
    w.add_body(s, m, 1.0, Vec3(0, 0, 3 * kR), Quat::Identity());
  }
  const double dt = 1e-3 * w.critical_time_step();
  // Poses the body i at rest with its circumsphere centre at `centre`.
  const auto place = [&](Index i, const Vec3& centre, const Quat& q) {
    BodyState& b = w.state.bodies[i];
    b.x = centre - q * t.centre_local;
    b.q = q;
    b.v.setZero();
    b.w.setZero();
  };
  Rng rng(7);
  const auto random_rotation = [&] {
    return Quat(Eigen::AngleAxisd(rng.uniform(0.0, 6.283185307179586), rng.unit_vector()));
  };
  const double fracs[3] = {0.01, 0.02, 0.04};
  double sum[3] = {0, 0, 0};
  HertzError err{0, 0};
  for (int o = 0; o < 6; ++o) {
    const Quat qa = random_rotation(), qb = random_rotation();
    for (int k = 0; k < 3; ++k) {
      const double frac = fracs[k];
      const double delta = frac * t.radius;
      if (two) {
        place(0, Vec3::Zero(), qa);
        place(1, Vec3(0, 0, 2 * t.radius - delta), qb);
      } else {
        place(0, Vec3(0, 0, t.radius - delta), qa);
      }
      // Forget the last pose's pairs and contacts: a fresh, cold collision.
      w.state.pairs.clear();
      w.state.wall_pairs.clear();
      w.state.contacts.clear();
      w.state.wall_contacts.clear();
      w.state.rebuild_pairs = true;
      w.step(dt);
      const auto& contacts = two ? w.state.contacts : w.state.wall_contacts;
      const double hertz = (4.0 / 3.0) * e_star * std::sqrt(r_star) * std::pow(delta, 1.5);
      const double f = contacts.size() == 1 ? contacts[0].normal_force : 0.0;
      sum[k] += f / hertz;
      err.worst = std::max(err.worst, std::abs(f / hertz - 1));
      if (std::getenv("GL_TRACE") && points > 5000)
        std::printf("  %d %.3f F/F_H %.4f depth/delta %.4f gain %.4f\n", o, frac, f / hertz,
                    contacts.empty() ? 0.0 : contacts[0].geo.depth / delta, contacts.empty() ? 0.0 : contacts[0].geo.gain);
    }
  }
  for (int k = 0; k < 3; ++k) err.mean = std::max(err.mean, std::abs(sum[k] / 6 - 1));
  return err;
}

}  // namespace

// Measured (mean / worst): 0.434 / 1.01 at 200 faces (often no vertex low
// enough to touch), 0.0271 / 0.295 at 2000, 0.00104 / 0.00655 at 20000.
TEST(FacetedHertz, TessellatedSphereOnPlaneConvergesToHertz) {
  const HertzError e200 = hertz_error(102, false), e2000 = hertz_error(1002, false),
                   e20000 = hertz_error(10002, false);
  std::printf("sphere on plane: Hertz error, mean over orientations %.3g (200 faces), %.3g (2000), %.3g (20000); "
              "worst %.3g, %.3g, %.3g\n", e200.mean, e2000.mean, e20000.mean, e200.worst, e2000.worst, e20000.worst);
  EXPECT_LT(e2000.mean, e200.mean);
  EXPECT_LT(e20000.mean, e2000.mean);
  EXPECT_LT(e20000.mean, 0.05);
  EXPECT_LT(e20000.worst, 0.05);
}

// Measured (mean / worst): 1 / 1 at 200 faces, 0.276 / 0.557 at 2000, 0.0318 /
// 0.0596 at 20000 (the overlap short by the faces' sag, see above).
TEST(FacetedHertz, TessellatedSpheresPressedTogetherConvergeToHertz) {
  const HertzError e200 = hertz_error(102, true), e2000 = hertz_error(1002, true),
                   e20000 = hertz_error(10002, true);
  std::printf("sphere on sphere: Hertz error, mean over orientations %.3g (200 faces), %.3g (2000), %.3g (20000); "
              "worst %.3g, %.3g, %.3g\n", e200.mean, e2000.mean, e20000.mean, e200.worst, e2000.worst, e20000.worst);
  EXPECT_LT(e2000.mean, e200.mean);
  EXPECT_LT(e20000.mean, e2000.mean);
  EXPECT_LT(e20000.mean, 0.05);
}
