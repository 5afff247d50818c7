// The recipe for a shape kind, followed in this one file: a solid ellipsoid,
// registered at run time (register_shape_kind, register_pair_routine), its
// bodies stepped by a World that names no kind. Its own parts: the geometry
// (semi-axes), a support map, two pair routines, and a builder that fills a
// Shape for Model::add_shape.
//
// Support map. The ellipsoid x^T A^-2 x <= 1, A = diag(a, b, c), reaches
// furthest along d at s(d) = A^2 d / |A d| (maximise d.x on the surface:
// d = mu A^-2 x, and x^T A^-2 x = 1 gives mu = |A d|); its support value is
// h(d) = |A d|. A body places it as p = pos + R (scale p_local), so
// s_world(d) = pos + scale R s(R^T d).
// Against a plane with unit normal n (grains on the +n side, through point
// o): the deepest point is s_world(-n), at depth (o - s_world(-n)).n =
// scale |A R^T n| - n.(pos - o).
// Against a sphere (centre x, radius r): GJK gives the distance from the
// ellipsoid to the point x; the depth is r minus that distance, along the
// line from the ellipsoid's nearest point to x.
// Mass: V = (4/3) pi a b c; principal moments per unit density
// V (b^2 + c^2) / 5, V (a^2 + c^2) / 5, V (a^2 + b^2) / 5.
//
// Checked against analytic values: a sphere centred at p + t m, with p a
// point of the surface and m its outward normal, lies at distance t from the
// ellipsoid along m (p is the nearest point: m is normal there and the
// ellipsoid convex); and a plane's depth is the support value above.
#include "collision/dispatch.h"
#include "collision/gjk.h"
#include "core/rng.h"
#include "dynamics/world.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>

using namespace grainlab;

namespace {

// The kind's geometry: its semi-axes at scale 1 (m), along its principal axes.
struct Ellipsoid {
  Vec3 semi;
};

// An ellipsoid placed in the world, as a support shape for GJK.
struct EllipsoidShape {
  Vec3 semi;
  Mat3 rot;
  Vec3 pos;
  double scale;

  explicit EllipsoidShape(const PosedShape& s)
      : semi(s.geometry_as<Ellipsoid>().semi), rot(*s.rot), pos(s.pos), scale(s.scale) {}
  Vec3 support(const Vec3& d) const {
    const Vec3 ad = semi.cwiseProduct(rot.transpose() * d);
    const double n = ad.norm();
    return n > 0 ? Vec3(pos + (scale / n) * (rot * semi.cwiseProduct(ad))) : pos;
  }
  Vec3 center() const { return pos; }
};

// Plane a (normal q * z) against ellipsoid b: exact.
int plane_ellipsoid(const PosedShape& a, const PosedShape& b, PairCache&, PairCache*, SubContact* out) {
  const Vec3 n = *a.q * Vec3::UnitZ();
  const Vec3 deepest = EllipsoidShape(b).support(-n);
  ContactResult r;
  r.normal = n;
  r.depth = (a.pos - deepest).dot(n);
  r.touching = r.depth > 0;
  r.point = deepest + 0.5 * r.depth * n;
  out[0] = {r, 0};
  return 1;
}

// Sphere a against ellipsoid b: GJK from the ellipsoid to a's centre, warm
// started from the pair's last direction; a centre inside the ellipsoid
// takes EPA on the whole sphere.
int sphere_ellipsoid(const PosedShape& a, const PosedShape& b, PairCache& c, PairCache*, SubContact* out) {
  const EllipsoidShape e(b);
  Vec3 dir = c.dir;
  ContactResult r = gjk_epa(SphereShape{a.pos, 0}, e, dir);
  if (r.depth < 0) {  // separated centre: distance -depth, normal from the centre to the ellipsoid
    const double dist = -r.depth;
    r.depth = a.radius - dist;
    r.touching = r.depth > 0;
    r.point = a.pos + 0.5 * (a.radius + dist) * r.normal;
  } else {
    dir = c.dir;
    r = gjk_epa(SphereShape{a.pos, a.radius}, e, dir);
  }
  c.dir = r.normal;
  out[0] = {r, 0};
  return 1;
}

// The kind and its table entries, registered once.
ShapeKind ellipsoid_kind() {
  static const ShapeKind kind = [] {
    const ShapeKind k = register_shape_kind("ellipsoid");
    register_pair_routine(ShapeKind::Plane, k, plane_ellipsoid, PairNeeds{.reads_cache = false});
    register_pair_routine(ShapeKind::Sphere, k, sphere_ellipsoid, PairNeeds{});
    return k;
  }();
  return kind;
}

Index add_ellipsoid_shape(Model& m, const Vec3& semi) {
  Shape s;
  s.kind = ellipsoid_kind();
  s.name = "ellipsoid";
  const double a2 = semi.x() * semi.x(), b2 = semi.y() * semi.y(), c2 = semi.z() * semi.z();
  s.volume = 4.0 / 3.0 * std::numbers::pi * semi.prod();
  s.unit_moments = s.volume / 5 * Vec3(b2 + c2, a2 + c2, a2 + b2);
  s.equivalent_radius = std::cbrt(semi.prod());
  s.bounding_radius = semi.maxCoeff();
  s.geometry = std::make_shared<const Ellipsoid>(Ellipsoid{semi});
  return m.add_shape(std::move(s));
}

// A point of the ellipsoid's surface (world) and its outward unit normal.
struct SurfacePoint {
  Vec3 p, m;
};
SurfacePoint surface_point(const Vec3& semi, const Quat& q, const Vec3& pos, double scale, const Vec3& u) {
  return {pos + scale * (q * semi.cwiseProduct(u)), q * u.cwiseQuotient(semi).normalized()};
}

const Vec3 kSemi(3e-3, 2e-3, 1e-3);  // m

}  // namespace

// Through the table alone: random poses, a sphere placed at depth delta over
// a random surface point, in both orders (one of them flipped).
TEST(EllipsoidKind, SphereContactHasTheAnalyticDepthNormalAndPoint) {
  Model model;
  const Index shape = add_ellipsoid_shape(model, kSemi);
  Rng rng(5);
  for (int k = 0; k < 40; ++k) {
    const Quat q(Eigen::AngleAxisd(rng.uniform(0, 3), rng.unit_vector()));
    const Mat3 rot = q.toRotationMatrix();
    const Vec3 pos(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
    const double scale = rng.uniform(0.5, 2), r = rng.uniform(0.2e-3, 2e-3), delta = rng.uniform(-0.2, 0.5) * r;
    const SurfacePoint sp = surface_point(kSemi, q, pos, scale, rng.unit_vector());
    PosedShape e;
    e.kind = model.shapes[shape].kind;
    e.geometry = model.shapes[shape].geometry.get();
    e.rot = &rot, e.q = &q, e.pos = pos, e.scale = scale;
    PosedShape s;
    s.kind = ShapeKind::Sphere;
    s.radius = r;
    s.pos = sp.p + (r - delta) * sp.m;
    PairCache cache;
    SubContact out[kMaxSubContacts];
    ASSERT_EQ(collide_shapes(e, s, cache, out), 1);  // flipped: registered as (sphere, ellipsoid)
    EXPECT_NEAR(out[0].geo.depth, delta, 1e-12) << k;
    EXPECT_EQ(out[0].geo.touching, delta > 0);
    // GJK stops on the distance (1e-12 of the size); on a curved surface the
    // direction is then good to about the square root of that.
    EXPECT_NEAR((out[0].geo.normal - sp.m).norm(), 0, 1e-5) << k;
    EXPECT_NEAR((out[0].geo.point - (sp.p - 0.5 * delta * sp.m)).norm(), 0, 1e-5 * r) << k;
    PairCache direct;
    ASSERT_EQ(collide_shapes(s, e, direct, out), 1);
    EXPECT_NEAR(out[0].geo.depth, delta, 1e-12) << k;
    EXPECT_NEAR((out[0].geo.normal + sp.m).norm(), 0, 1e-5) << k;
  }
}

// The whole step: an ellipsoid pressed into a plane wall and touched by a
// sphere, in a World. The contacts of the first step (found before anything
// moves) have the analytic depths and normals, carry force, and push the
// sphere away along the normal.
TEST(EllipsoidKind, WorldStepsItsBodiesWithTheAnalyticContacts) {
  World w;
  const Index material = w.model.add_material(Material{});
  const Index ellipsoid = add_ellipsoid_shape(w.model, kSemi);
  const Index sphere = w.model.add_sphere_shape(0.6e-3);
  const Quat q = Quat(Eigen::AngleAxisd(0.4, Vec3::UnitX())) * Quat(Eigen::AngleAxisd(0.3, Vec3::UnitZ()));
  const double scale = 1.2, plane_depth = 20e-6, sphere_depth = 15e-6, r = 0.6e-3;
  // Height of the centre above the plane z = 0 for the wanted depth: scale |A R^T z| - depth.
  const double h = scale * kSemi.cwiseProduct(q.inverse() * Vec3::UnitZ()).norm() - plane_depth;
  const Vec3 pos(0, 0, h);
  const SurfacePoint sp = surface_point(kSemi, q, pos, scale, Vec3::UnitX());  // the tip of the long axis
  w.add_body(ellipsoid, material, scale, pos, q);
  w.add_body(sphere, material, 1.0, sp.p + (r - sphere_depth) * sp.m);
  w.add_plane(Vec3::Zero(), Vec3::UnitZ(), material);
  w.step(0.1 * w.critical_time_step());

  ASSERT_EQ(w.state.wall_contacts.size(), 1u);
  const Contact& wall = w.state.wall_contacts[0];
  EXPECT_EQ(wall.b, 0);
  EXPECT_NEAR(wall.geo.depth, plane_depth, 1e-15);
  EXPECT_NEAR((wall.geo.normal - Vec3::UnitZ()).norm(), 0, 1e-15);
  EXPECT_GT(wall.normal_force, 0);

  ASSERT_EQ(w.state.contacts.size(), 1u);
  const Contact& grains = w.state.contacts[0];
  EXPECT_EQ(grains.a, 0);
  EXPECT_EQ(grains.b, 1);
  EXPECT_NEAR(grains.geo.depth, sphere_depth, 1e-15);
  EXPECT_NEAR((grains.geo.normal - sp.m).norm(), 0, 1e-5);  // from the ellipsoid (a) to the sphere (b)
  EXPECT_GT(grains.normal_force, 0);
  EXPECT_GT(w.body_forces()[1].dot(sp.m), 0);
  EXPECT_GT(w.state.bodies[1].v.dot(sp.m), 0);
}
