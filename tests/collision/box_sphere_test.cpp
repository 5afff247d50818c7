// Exact box-sphere against GJK/EPA (the general routine it replaces) on random
// boxes and spheres: beside a face, an edge or a corner, and with the centre
// inside the box; plus hand-checked cases. (EPA's point for a sphere on a box
// face was any point of the face, off the sphere's centre line by up to a
// millimetre here: a spurious torque on beads pressed on box walls.)
#include "collision/narrowphase.h"
#include "collision/test_shapes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace grainlab {
namespace {

TEST(BoxSphere, MatchesGjkEpaOnRandomPairs) {
  Rng rng(7);
  int touching = 0, inside = 0, compared = 0;
  for (int t = 0; t < 4000; ++t) {
    BoxShape box{rng.rotation().toRotationMatrix(), rng.unit_vector() * 1e-2,
                 Vec3(rng.uniform(0.5, 3), rng.uniform(0.5, 3), rng.uniform(0.5, 3)) * 1e-3};
    const double radius = rng.uniform(0.3, 0.5) * 1e-3;
    // A centre in the box's frame within +-(h + 0.6 mm): outside near a face,
    // edge or corner, or inside.
    Vec3 c_local;
    for (int i = 0; i < 3; ++i) c_local[i] = rng.uniform(-1, 1) * (box.half[i] + 0.6e-3);
    const SphereShape sphere{box.pos + box.rot * c_local, radius};
    const ContactResult exact = collide(box, sphere);
    const bool centre_inside = (c_local.cwiseAbs() - box.half).maxCoeff() <= 0;
    if (centre_inside) {
      // Skip near-ties between two faces: either is a minimum translation.
      Vec3 clearance = box.half - c_local.cwiseAbs();
      std::sort(clearance.data(), clearance.data() + 3);
      if (clearance[1] - clearance[0] < 1e-6) continue;
      ++inside;
    }
    // GJK/EPA finds separations as well as depths only near contact; compare within 0.2 mm of touching.
    if (exact.depth < -0.2e-3) continue;
    Vec3 dir = Vec3::UnitX();
    const ContactResult ref = collide_convex(box, sphere, dir);
    ++compared;
    touching += exact.touching;
    EXPECT_EQ(exact.touching, ref.touching) << t;
    // GJK/EPA stop at a relative tolerance (measured: depths within 5e-10 m,
    // normals within 4e-5, points within 8e-9 m on these millimetre shapes),
    // and from one side: EPA's depth bounds the true one from above, GJK's
    // distance bounds the true one from above. The exact answer is never worse.
    EXPECT_NEAR(exact.depth, ref.depth, 2e-9) << t;
    if (exact.touching) EXPECT_LE(exact.depth, ref.depth + 1e-15) << t;
    else EXPECT_GE(exact.depth, ref.depth - 1e-15) << t;
    // EPA's normal is off by up to 3e-3 where a corner's sphere of support
    // meets the box (measured 2.9e-3); its point is not unique on a face (any
    // point of the face gives the same translation), so the exact point is
    // checked by what defines it: on the line through the centre along the
    // normal, midway between the surfaces (c - r n and c - (r - depth) n).
    if (std::abs(exact.depth) > 1e-9) {
      EXPECT_LT((exact.normal - ref.normal).norm(), 5e-3) << t;
    }
    const Vec3 midway = sphere.pos - (radius - 0.5 * exact.depth) * exact.normal;
    EXPECT_LT((exact.point - midway).norm(), 1e-15) << t;
    EXPECT_NEAR(exact.normal.norm(), 1, 1e-14);
    // Moving the sphere by depth * normal makes the shapes just touch.
    const ContactResult moved = collide(box, SphereShape{sphere.pos + exact.depth * exact.normal, radius});
    EXPECT_NEAR(moved.depth, 0, 1e-15) << t;
  }
  EXPECT_GT(compared, 1000);
  EXPECT_GT(touching, 300);
  EXPECT_GT(inside, 50);
}

TEST(BoxSphere, HandCheckedFaceEdgeCornerAndInside) {
  const BoxShape box{Mat3::Identity(), Vec3::Zero(), Vec3(1, 2, 3)};
  // Above the top face, 0.2 into it.
  ContactResult r = collide(box, SphereShape{Vec3(0.3, -0.4, 3.3), 0.5});
  EXPECT_TRUE(r.touching);
  EXPECT_NEAR(r.depth, 0.2, 1e-15);
  EXPECT_LT((r.normal - Vec3::UnitZ()).norm(), 1e-15);
  EXPECT_LT((r.point - Vec3(0.3, -0.4, 2.9)).norm(), 1e-15);  // between z = 3 and z = 2.8
  // Beyond the edge x = 1, y = 2, diagonally: distance sqrt(0.08).
  r = collide(box, SphereShape{Vec3(1.2, 2.2, 0), 0.5});
  EXPECT_NEAR(r.depth, 0.5 - std::sqrt(0.08), 1e-15);
  EXPECT_LT((r.normal - Vec3(1, 1, 0).normalized()).norm(), 1e-15);
  // Beyond a corner, apart.
  r = collide(box, SphereShape{Vec3(2, 3, 4), 0.5});
  EXPECT_FALSE(r.touching);
  EXPECT_NEAR(r.depth, 0.5 - std::sqrt(3.0), 1e-15);
  // Centre inside, nearest the -y face (clearance 0.5): out along -y.
  r = collide(box, SphereShape{Vec3(0, -1.5, 0.5), 0.25});
  EXPECT_NEAR(r.depth, 0.75, 1e-15);
  EXPECT_LT((r.normal + Vec3::UnitY()).norm(), 1e-15);
  EXPECT_LT((r.point - Vec3(0, -0.5 * (2 + 1.25), 0.5)).norm(), 1e-15);  // between y = -2 and y = -1.25
}

}  // namespace
}  // namespace grainlab
