// Concave grains in contact (issue 12 item 1): a grain collided as the convex
// pieces of decompose_convex keeps its dents, where its convex hull fills
// them in.
//  - A small sphere lies in the trough of a U-shaped grain. As pieces, it
//    rests on the trough's floor; as the hull, it starts 1.5 mm deep inside
//    the grain and is thrown out.
//  - A hook (an upside-down U) hangs over one wall of the U and is pulled
//    sideways: as pieces it slides until its leg catches the wall and stays
//    hooked, a pull that only a concave contact can carry; as hulls the two
//    overlap by a square millimetre and fly apart.
//  - A sphere pressed into the flat underside of the U, across the seams
//    where its pieces meet, feels the hull's force there (exact on that
//    face) within 10 %: one contact's force, not one per piece
//    (routines_compound.cpp).
//  - Two dented grains touching in random poses give the same contacts
//    whatever direction the pair routine tests separating planes along
//    (that pruning may only skip pieces that are apart).
//  - A convex grain given as one piece collides as its hull does: the same
//    force on a sphere pressed onto it (the compound path collides pieces
//    cold, so the same geometry, not the same bits).
// The U grain is held at its pose before every step (infinite mass).
// Lengths in mm scale (1e-3 m), soft grains (E = 1e7 Pa) for a long step.
#include "dynamics/world.h"
#include "geometry/convex_decomposition.h"
#include "geometry/mass_properties.h"
#include "geometry/primitives.h"
#include "collision/dispatch.h"
#include "core/rng.h"
#include "grains/generator.h"

#include <gtest/gtest.h>

#include <vector>

using namespace grainlab;

namespace {

constexpr double mm = 1e-3;

TriMesh scaled(TriMesh m, double s) {
  for (Vec3& v : m.vertices) v *= s;
  return m;
}

// A U open towards +y: 6 wide, 3 high, bars 1 thick, 2 deep (mm).
TriMesh u_grain() {
  return scaled(prism_mesh({{-3, 0}, {3, 0}, {3, 3}, {2, 3}, {2, 1}, {-2, 1}, {-2, 3}, {-3, 3}}, 1.0), mm);
}

// A hook over the U's right wall: a bar on top (y 3.05 to 3.85), legs 0.8
// wide down to y 2.05, 0.2 mm clear of the wall on either side.
TriMesh hook_grain() {
  return scaled(prism_mesh({{1, 2.05}, {1.8, 2.05}, {1.8, 3.05}, {3.2, 3.05}, {3.2, 2.05}, {4, 2.05}, {4, 3.85},
                            {1, 3.85}},
                           1.0),
                mm);
}

enum class As { Pieces, Hull };

// Adds a grain of this mesh, placed where the mesh lies; returns the body.
Index add_grain(World& w, const TriMesh& mesh, As as, Index material) {
  const Index shape = as == As::Pieces ? w.model.add_concave_shape(mesh, decompose_convex(mesh), "concave")
                                       : w.model.add_mesh_shape(mesh, "hull");
  const MassProperties mp = mass_properties(mesh);
  return w.add_body(shape, material, 1.0, mp.centroid, Quat(mp.principal_axes));
}

Material soft() {
  Material m;
  m.youngs_modulus = 1e7;
  m.restitution = 0.3;
  m.friction = 0.3;
  return m;
}

// Steps for `seconds`, holding body `held` at its starting pose.
void run_holding(World& w, Index held, double seconds) {
  const BodyState pose = w.state.bodies[held];
  const double dt = 0.2 * w.critical_time_step();
  for (double t = 0; t < seconds; t += dt) {
    BodyState& b = w.state.bodies[held];
    b.x = pose.x;
    b.q = pose.q;
    b.v = b.w = Vec3::Zero();
    w.step(dt);
  }
}

struct SphereInTrough {
  Vec3 start, end;
  double speed;
};

SphereInTrough sphere_in_trough(As as) {
  World w;
  w.model.gravity = Vec3(0, -9.81, 0);
  const Index mat = w.model.add_material(soft());
  const Index u = add_grain(w, u_grain(), as, mat);
  const Index ball = w.add_body(w.model.add_sphere_shape(0.5 * mm), mat, 1.0, Vec3(0.3 * mm, 1.52 * mm, 0));
  SphereInTrough r{w.state.bodies[ball].x, {}, 0};
  run_holding(w, u, 0.05);
  r.end = w.state.bodies[ball].x;
  r.speed = w.state.bodies[ball].v.norm();
  return r;
}

// A sub-angular grain of 200 faces with dents (convexity 0.85), unit size.
TriMesh dented_grain(std::uint64_t seed) {
  GeneratorSpec g = preset_spec(GrainPreset::SubAngular);
  g.faces = 200;
  g.convexity = 0.85;
  Rng rng(seed);
  return generate_grain(g, rng);
}

// The distance along u from body a (at the origin) at which body b first
// touches it, by bisection over [0, 3] (grains of unit size).
double touching_distance(World& w, Index a, Index b, const Vec3& u) {
  SubContact out[kMaxSubContacts];
  double lo = 0, hi = 3;
  for (int it = 0; it < 50; ++it) {
    const double mid = 0.5 * (lo + hi);
    w.state.bodies[b].x = mid * u;
    PairCache cold;
    (collide_shapes(w.posed_body(a), w.posed_body(b), cold, out) > 0 ? lo : hi) = mid;
  }
  return lo;
}

}  // namespace

TEST(ConcaveContact, ASphereRestsInTheTroughOfAUGrainThatItsHullWouldFill) {
  const SphereInTrough pieces = sphere_in_trough(As::Pieces);
  // On the floor (y = 1 mm) under its own weight: centre 0.5 mm above it, less a tiny overlap
  // (measured: x 0.29998 mm, y 1.49979 mm, 1.6e-6 m/s; the hull threw it 0.67 m).
  EXPECT_NEAR(pieces.end.y(), 1.5 * mm, 0.01 * mm);
  EXPECT_LT(std::abs(pieces.end.x()), 1.5 * mm);  // still in the trough (walls at +-2 mm)
  EXPECT_LT(pieces.speed, 1e-3);                  // m/s

  const SphereInTrough hull = sphere_in_trough(As::Hull);
  // The hull's top is at y = 3 mm: the sphere is thrown out of it.
  EXPECT_GT((hull.end - hull.start).norm(), 1.5 * mm) << hull.end.transpose();
}

namespace {

struct Hooked {
  Vec3 moved;
  double speed;
};

Hooked pull_the_hook(As as) {
  World w;
  w.model.gravity = Vec3(0.5 * 9.81, -9.81, 0);  // down, and pulled towards +x
  const Index mat = w.model.add_material(soft());
  const Index u = add_grain(w, u_grain(), as, mat);
  const Index hook = add_grain(w, hook_grain(), as, mat);
  const Vec3 start = w.state.bodies[hook].x;
  run_holding(w, u, 0.08);
  return {w.state.bodies[hook].x - start, w.state.bodies[hook].v.norm()};
}

}  // namespace

TEST(ConcaveContact, AHookPulledSidewaysCatchesTheWallOfAUGrain) {
  const Hooked pieces = pull_the_hook(As::Pieces);
  // It drops 0.05 mm onto the wall and slides 0.2 mm until its leg catches
  // the wall's inner face, then stays (friction 0.3 < the pull's 0.5).
  // Measured: moved 0.190 mm along x (0.2 less the overlap), -0.0505 mm along y, at rest.
  EXPECT_NEAR(pieces.moved.x(), 0.2 * mm, 0.02 * mm) << pieces.moved.transpose();
  EXPECT_NEAR(pieces.moved.y(), -0.05 * mm, 0.02 * mm) << pieces.moved.transpose();
  EXPECT_LT(pieces.speed, 1e-3);

  const Hooked hull = pull_the_hook(As::Hull);
  EXPECT_GT(hull.moved.norm(), 1 * mm) << hull.moved.transpose();
}

TEST(ConcaveContact, AConvexGrainAsOnePieceCollidesAsItsHull) {
  const TriMesh grain = scaled(ellipsoid_mesh(2, 1.5, 1, 2), mm);
  Vec3 force[2];
  for (int k = 0; k < 2; ++k) {
    World w;
    w.model.gravity = Vec3::Zero();
    const Index mat = w.model.add_material(soft());
    const Index shape = k == 0 ? w.model.add_mesh_shape(grain, "hull")
                               : w.model.add_concave_shape(grain, ConvexDecomposition{{grain.vertices}, {{}}}, "one piece");
    w.add_body(shape, mat, 1.0, Vec3::Zero(), Quat(Eigen::AngleAxisd(0.3, Vec3(1, 2, 3).normalized())));
    // A sphere pressed 10 um into the grain from above, off centre.
    const Index ball = w.add_body(w.model.add_sphere_shape(0.5 * mm), mat, 1.0, Vec3(0.4 * mm, 0.3 * mm, 0));
    const double top = [&] {  // highest point of the posed grain under the ball: bisect along +z
      double lo = 0, hi = 3 * mm;
      for (int it = 0; it < 60; ++it) {
        const double mid = 0.5 * (lo + hi);
        w.state.bodies[ball].x.z() = mid;
        w.step(1e-12);
        (w.state.contacts.empty() ? hi : lo) = mid;
      }
      return lo;
    }();
    w.state.bodies[ball].x.z() = top - 10e-6;
    w.state.bodies[ball].v = Vec3::Zero();
    w.step(1e-9);
    force[k] = Vec3::Zero();
    for (const Contact& c : w.state.contacts) force[k] += c.force;  // on the ball (b)
  }
  EXPECT_GT(force[0].norm(), 0) << force[1].transpose();
  // GJK/EPA stop within a tolerance, warm (hull) or cold (piece): measured 7e-5 apart.
  EXPECT_NEAR((force[1] - force[0]).norm(), 0, 1e-3 * force[0].norm())
      << force[0].transpose() << " / " << force[1].transpose();
}

// A sphere 10 um deep under the U's flat underside, moving with `velocity`,
// at every 0.02 mm along the underside's 6 mm (the seams lie where cuts meet
// y = 0): the total force on it of the U as its hull (first) and as pieces.
std::vector<std::pair<double, double>> forces_along_the_underside(const Vec3& velocity) {
  const TriMesh u = u_grain();
  const ConvexDecomposition dec = decompose_convex(u);
  EXPECT_GE(dec.pieces.size(), 3u);
  const MassProperties mp = mass_properties(u);
  World w[2];
  Index ball[2];
  for (int k = 0; k < 2; ++k) {
    w[k].model.gravity = Vec3::Zero();
    const Index mat = w[k].model.add_material(soft());
    const Index shape = k == 0 ? w[k].model.add_mesh_shape(u, "hull") : w[k].model.add_concave_shape(u, dec, "pieces");
    w[k].add_body(shape, mat, 1.0, mp.centroid, Quat(mp.principal_axes));
    ball[k] = w[k].add_body(w[k].model.add_sphere_shape(0.5 * mm), mat, 1.0, Vec3::Zero());
  }
  std::vector<std::pair<double, double>> out;
  for (double x = -2.9 * mm; x <= 2.9 * mm; x += 0.02 * mm) {
    double f[2];
    for (int k = 0; k < 2; ++k) {
      w[k].state.bodies[0].v = w[k].state.bodies[0].w = Vec3::Zero();
      w[k].state.bodies[ball[k]].x = Vec3(x, -0.5 * mm + 10e-6, 0);
      w[k].state.bodies[ball[k]].v = velocity;
      w[k].state.bodies[ball[k]].w = Vec3::Zero();
      for (Contact& c : w[k].state.contacts) c.xi = Vec3::Zero();
      w[k].step(1e-12);
      Vec3 sum = Vec3::Zero();
      for (const Contact& c : w[k].state.contacts) sum += c.force;  // on the ball (b)
      f[k] = sum.norm();
    }
    out.emplace_back(f[0], f[1]);
  }
  return out;
}

TEST(ConcaveContact, ASpherePressedAcrossTheSeamsOfAFlatFaceFeelsTheHullsForce) {
  // At rest: the elastic force (without weigh_seams, 55 of 581 positions
  // felt up to twice the force). Moving into the face and along it at
  // 0.2 m/s: the damping and the tangential force too, which the results
  // along a seam share as they share the elastic force (ContactResult::share;
  // without it they felt up to 1.52 times the hull's force at the seams).
  const Vec3 moving(0.2, 0.2, 0.1);
  const auto at_rest = forces_along_the_underside(Vec3::Zero());
  const auto sliding = forces_along_the_underside(moving);
  ASSERT_EQ(at_rest.size(), sliding.size());
  for (std::size_t i = 0; i < at_rest.size(); ++i) {
    const double x = -2.9 + 0.02 * static_cast<double>(i);
    // Shared smoothly (weigh_seams): at most 10 % under where a corner of the
    // next piece fades out (measured: 0.915 at worst), never over at rest,
    // and within 1 % over when moving (measured: 0.18 %; the pieces'
    // normals and points are not exactly the hull's).
    const auto [hull_rest, pieces_rest] = at_rest[i];
    const auto [hull_moving, pieces_moving] = sliding[i];
    ASSERT_GT(hull_rest, 0);
    EXPECT_LE(pieces_rest, hull_rest * (1 + 1e-6)) << "x = " << x << " mm";
    EXPECT_GE(pieces_rest, 0.9 * hull_rest) << "x = " << x << " mm";
    EXPECT_LE(pieces_moving, hull_moving * 1.01) << "x = " << x << " mm, moving";
    EXPECT_GE(pieces_moving, 0.9 * hull_moving) << "x = " << x << " mm, moving";
    // The motion matters: the damping and friction forces are not small.
    EXPECT_GT(sliding[i].first, 1.3 * at_rest[i].first) << "x = " << x << " mm";
  }
}

TEST(ConcaveContact, PieceContactsDoNotDependOnThePairsTestDirection) {
  const TriMesh ma = dented_grain(100), mb = dented_grain(101);
  World w;
  w.model.gravity = Vec3::Zero();
  const Index a = w.add_body(w.model.add_concave_shape(ma, decompose_convex(ma), "a"), 0, 1.0, Vec3::Zero());
  const Index b = w.add_body(w.model.add_concave_shape(mb, decompose_convex(mb), "b"), 0, 1.0, Vec3::Zero());
  Rng rng(7);
  SubContact out[kMaxSubContacts], ref[kMaxSubContacts];
  int touching = 0;
  for (int pose = 0; pose < 60; ++pose) {
    w.state.bodies[a].q = rng.rotation();
    w.state.bodies[b].q = rng.rotation();
    const Vec3 u = rng.unit_vector();
    w.step(1e-30);  // pose the rotations
    w.state.bodies[b].x = (touching_distance(w, a, b, u) - 0.005) * u;
    PairCache cold;
    const int n_ref = collide_shapes(w.posed_body(a), w.posed_body(b), cold, ref);
    touching += n_ref > 0;
    for (int t = 0; t < 5; ++t) {
      PairCache c;
      c.warm = true;
      c.dir = rng.unit_vector();
      const int n = collide_shapes(w.posed_body(a), w.posed_body(b), c, out);
      ASSERT_EQ(n, n_ref) << "pose " << pose;
      for (int k = 0; k < n; ++k) {
        EXPECT_EQ(out[k].sub, ref[k].sub);
        EXPECT_EQ(out[k].geo.depth, ref[k].geo.depth);
      }
    }
  }
  EXPECT_EQ(touching, 60);
}

// The piece pairs of a pair of concave grains keep their caches between
// steps (CandidatePair::pieces) as a convex pair does; a cache only starts
// GJK elsewhere, so the contacts must follow those of cold pieces. Two dented
// grains pressed together, one creeping and turning for 100 steps, in three
// orders: both concave, concave against a hull (the table flips that pair and
// its piece caches) and a hull against concave.
TEST(ConcaveContact, PieceContactsWithKeptCachesFollowColdOnesAsThePairMoves) {
  const TriMesh ma = dented_grain(200), mb = dented_grain(201);
  enum class Kinds { ConcaveConcave, ConcaveHull, HullConcave };
  int warm_pieces = 0, compared = 0;
  for (const Kinds kinds : {Kinds::ConcaveConcave, Kinds::ConcaveHull, Kinds::HullConcave}) {
    World w;
    w.model.gravity = Vec3::Zero();
    const auto shape = [&](const TriMesh& m, bool concave) {
      return concave ? w.model.add_concave_shape(m, decompose_convex(m), "c") : w.model.add_mesh_shape(m, "h");
    };
    const Index a = w.add_body(shape(ma, kinds != Kinds::HullConcave), 0, 1.0, Vec3::Zero());
    const Index b = w.add_body(shape(mb, kinds != Kinds::ConcaveHull), 0, 1.0, Vec3::Zero());
    Rng rng(9);
    SubContact out[kMaxSubContacts], ref[kMaxSubContacts];
    for (int pose = 0; pose < 8; ++pose) {
      w.state.bodies[a].q = rng.rotation();
      w.state.bodies[b].q = rng.rotation();
      const Vec3 u = rng.unit_vector();
      w.step(1e-30);  // pose the rotations
      w.state.bodies[b].x = (touching_distance(w, a, b, u) + 0.002) * u;  // 0.002 apart, creeping in 1e-4 a step
      const int np = piece_cache_count(w.posed_body(a), w.posed_body(b));
      ASSERT_GT(np, 1);
      std::vector<PairCache> pieces(static_cast<std::size_t>(np));
      PairCache kept, cold_pair;
      const Vec3 creep = -1e-4 * u + 2e-5 * rng.unit_vector();
      const Vec3 spin = 1e-4 * rng.unit_vector();
      for (int step = 0; step < 100; ++step) {
        w.state.bodies[b].x += creep;
        w.state.bodies[b].q = (Quat(Eigen::AngleAxisd(spin.norm(), spin.normalized())) * w.state.bodies[b].q).normalized();
        w.step(1e-30);
        PairCache cold = cold_pair;
        const int n_ref = collide_shapes(w.posed_body(a), w.posed_body(b), cold, ref);
        cold_pair = cold;  // the pair's own direction carries over in both
        const int n = collide_shapes(w.posed_body(a), w.posed_body(b), kept, out, pieces.data());
        ASSERT_EQ(n, n_ref) << "pose " << pose << " step " << step;
        for (int k = 0; k < n; ++k) {
          ASSERT_EQ(out[k].sub, ref[k].sub);
          ASSERT_EQ(out[k].geo.touching, ref[k].geo.touching);
          EXPECT_NEAR(out[k].geo.depth, ref[k].geo.depth, 1e-9 * std::abs(ref[k].geo.depth) + 1e-15)
              << "pose " << pose << " step " << step;
          EXPECT_LT((out[k].geo.normal - ref[k].geo.normal).norm(), 1e-7) << "pose " << pose << " step " << step;
          EXPECT_LT((out[k].geo.point - ref[k].geo.point).norm(), 1e-9) << "pose " << pose << " step " << step;
          ++compared;
        }
        for (const PairCache& c : pieces) warm_pieces += c.warm && c.simplex.n > 0;
        // Each touching piece pair's cache is kept for a to b, as the pair's
        // own: its direction is the contact normal's (a flip left undone
        // would point it back).
        for (int k = 0; k < n; ++k) {
          const PairCache& c = pieces[static_cast<std::size_t>(out[k].sub)];
          EXPECT_GT(c.dir.normalized().dot(out[k].geo.normal), 0.5) << "pose " << pose << " step " << step;
        }
      }
    }
  }
  EXPECT_GT(compared, 500);
  EXPECT_GT(warm_pieces, 500);  // the caches were kept and used
}
