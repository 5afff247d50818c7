// The four-lane contact law (dynamics/contact_lanes.h, what the World runs)
// against the one-contact reference contact_force (contact_force_reference.h),
// for every registered law, on random contacts: approaching and separating
// (the no-tension clamp), sticking and sliding (the Coulomb cap), springs
// that are zero, tilted out of the tangent plane or lying along the normal,
// and unlike materials in neighbouring lanes. The two may round differently
// (FMA contraction is the compiler's), so they agree to 1e-12 of the
// contact's force scale, not bit for bit.
#include "contact_force_reference.h"
#include "dynamics/contact_lanes.h"
#include "dynamics/laws/registry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

using namespace grainlab;

namespace {

Material random_material(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0, 1);
  Material m;
  m.friction = u(rng) < 0.2 ? 0.0 : 0.6 * u(rng);
  m.youngs_modulus = std::pow(10.0, 8 + 3 * u(rng));
  m.poisson_ratio = 0.45 * u(rng);
  m.restitution = 0.2 + 0.2 * static_cast<int>(4 * u(rng));  // a few values: beta is solved once for each
  m.k_n = std::pow(10.0, 5 + 7 * u(rng));
  m.k_t = (0.5 + 0.5 * u(rng)) * m.k_n;
  m.gamma_n = 100 * u(rng);
  m.gamma_t = 100 * u(rng);
  return m;
}

Vec3 random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  Vec3 v(g(rng), g(rng), g(rng));
  return v.normalized();
}

}  // namespace

TEST(ContactLanes, FourContactsAtOnceGiveWhatOneAtATimeGives) {
  std::mt19937_64 rng(19);
  std::uniform_real_distribution<double> u(0, 1);
  for (std::size_t law_i = 0; law_i < RegisteredLaws::size; ++law_i) {
    const ContactLaw law = ContactLaw::at_index(law_i);
    int sliding = 0, sticking = 0, clamped = 0;
    for (int trial = 0; trial < 2000; ++trial) {
      PairCoefficients pair[kLanes];
      ContactKinematics kin[kLanes];
      Vec3 xi[kLanes];
      ContactLanes lanes;
      PairCoefficientsOf<Lanes> p;
      const double dt = 1e-7 * (1 + u(rng));
      for (int l = 0; l < kLanes; ++l) {
        pair[l] = mix(random_material(rng), random_material(rng), law);
        ContactKinematics& c = kin[l];
        c.normal = random_unit(rng);
        const double size = 1e-4 + 1e-3 * u(rng);
        c.delta = size * std::pow(10.0, -6 + 4 * u(rng));
        c.v_rel = std::pow(10.0, -4 + 3 * u(rng)) * random_unit(rng);
        c.m_eff = 1e-9 + 1e-6 * u(rng);
        c.r_eff = 0.5 * size;
        c.gain = 0.5 + u(rng);
        c.share = u(rng) < 0.7 ? 1.0 : u(rng);  // a concave pair's result along a seam: a share of one contact
        if (u(rng) < 0.1) {  // separating fast enough that the damper outpulls the spring: f_n clamps at 0
          const LawCoefficients k = law->at(pair[l], c.delta, c.r_eff, c.m_eff);
          c.v_rel += (k.c_n > 0 ? 2 * c.gain * k.k_n * c.delta / (c.share * k.c_n) : 0.0) * c.normal;
        }
        const double kind = u(rng);
        // Zero, nearly along the normal (turned through up to 89.4 degrees), or anywhere.
        // (A spring exactly along the normal is turned into the direction of
        // its rounding residue, which is noise in either code.)
        const double length = c.delta * std::pow(10.0, -2 + 3 * u(rng));
        xi[l] = kind < 0.15   ? Vec3::Zero()
                : kind < 0.25 ? Vec3(length * (c.normal + 0.01 * random_unit(rng)))
                              : Vec3(length * random_unit(rng));
        lanes.nx[l] = c.normal.x(), lanes.ny[l] = c.normal.y(), lanes.nz[l] = c.normal.z();
        lanes.delta[l] = c.delta, lanes.gain[l] = c.gain, lanes.share[l] = c.share;
        lanes.vx[l] = c.v_rel.x(), lanes.vy[l] = c.v_rel.y(), lanes.vz[l] = c.v_rel.z();
        lanes.m_eff[l] = c.m_eff, lanes.r_eff[l] = c.r_eff;
        lanes.xix[l] = xi[l].x(), lanes.xiy[l] = xi[l].y(), lanes.xiz[l] = xi[l].z();
        for (int i = 0; i < kPairSlots; ++i) p.c[i][l] = pair[l].c[i];
        p.friction[l] = pair[l].friction;
      }
      const ForceLanes f = with_law(law, [&]<typename Law>() { return contact_force_lanes<Law>(p, lanes, dt); });
      for (int l = 0; l < kLanes; ++l) {
        double f_n = 0;
        LawCoefficients k{};
        Vec3 spring = xi[l];
        const Vec3 force = with_law(law, [&]<typename Law>() {
          return contact_force<Law>(pair[l], kin[l], dt, spring, &f_n, &k);
        });
        const double scale = std::max(force.norm(), 1e-300);
        // A sliding spring is -(f_t + C_t v_t)/K_t: its two terms may nearly
        // cancel, so its rounding is relative to theirs, not to the result.
        const double xi_scale = std::max(
            spring.norm() + xi[l].norm() + (force.norm() + k.c_t * kin[l].v_rel.norm()) / std::max(k.k_t, 1e-300),
            1e-300);
        EXPECT_NEAR(f.fx[l], force.x(), 1e-12 * scale) << contact_law_name(law) << " trial " << trial;
        EXPECT_NEAR(f.fy[l], force.y(), 1e-12 * scale);
        EXPECT_NEAR(f.fz[l], force.z(), 1e-12 * scale);
        EXPECT_NEAR(f.f_n[l], f_n, 1e-12 * scale);
        EXPECT_NEAR(lanes.xix[l], spring.x(), 1e-12 * xi_scale) << contact_law_name(law) << " trial " << trial;
        EXPECT_NEAR(lanes.xiy[l], spring.y(), 1e-12 * xi_scale);
        EXPECT_NEAR(lanes.xiz[l], spring.z(), 1e-12 * xi_scale);
        EXPECT_NEAR(f.k.k_n[l], k.k_n, 1e-14 * std::abs(k.k_n));
        EXPECT_NEAR(f.k.c_n[l], k.c_n, 1e-14 * std::abs(k.c_n));
        EXPECT_NEAR(f.k.k_t[l], k.k_t, 1e-14 * std::abs(k.k_t));
        EXPECT_NEAR(f.k.c_t[l], k.c_t, 1e-14 * std::abs(k.c_t));
        const Vec3 f_t = force - f_n * kin[l].normal;
        if (f_n == 0) ++clamped;
        else if (f_t.norm() >= pair[l].friction * f_n * (1 - 1e-9)) ++sliding;
        else ++sticking;
      }
    }
    // The cases above all occurred for this law.
    std::printf("%s: %d clamped, %d sliding, %d sticking\n", contact_law_name(law), clamped, sliding, sticking);
    EXPECT_GT(clamped, 100) << contact_law_name(law);
    EXPECT_GT(sliding, 100) << contact_law_name(law);
    EXPECT_GT(sticking, 100) << contact_law_name(law);
  }
}
