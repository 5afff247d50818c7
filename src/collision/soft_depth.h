// The conservative contact of faceted shapes: one potential per pair, a
// function of the depths of the vertices lying inside the other shape.
//
// Why. A force f(PD) n at the penetration-depth witness point is the exact
// gradient of u(PD) (envelope theorem), but PD of a flat face on a plane is
// the MAX of its corners' depths: the potential has a V-shaped kink at the
// flat position, the witness jumps from corner to corner each step as the face
// rocks, and the explicit step chatters. The depth-weighted centroid (the
// previous fix) is smooth but its torque is not -dU/dtheta: the force field
// is not a gradient, and a rocking face gains energy every cycle
// (tests/dynamics/resting_contact_test.cpp measures both).
//
// The potential. Vertex i of either shape lying inside the other has depth
// d_i > 0 (its distance inside the other's nearest face plane, or below a
// wall), a continuous, piecewise smooth function of the two poses that is 0
// when the vertex enters. The pair's potential is U = u(D), u the contact
// law's elastic energy, with the smooth maximum
//     D = kappa S_{k+1} / S_k,   S_j = sum_i d_i^j,   k = 4,   kappa = (k+2)/(k+1) = 6/5.
// D is continuous (a vertex enters with weight 0), smooth where the d_i are,
// and lies between kappa times the mean and kappa times the max depth.
// kappa makes a finely tessellated sphere follow the law exactly: with
// vertices evenly spread over a cap of depth delta, d = delta - rho^2/(2R),
// S_j = 2 pi R n delta^{j+1}/(j+1), so D = kappa (k+1)/(k+2) delta = delta.
//
// The forces (exact gradient). dD/dd_i = kappa d_i^{k-1} ((k+1) d_i S_k -
// k S_{k+1}) / S_k^2 = g_i. Vertex i carries u'(D) g_i along u_i, the outward
// normal of the other shape's face that is nearest (pushing the vertex out),
// so with the unit vectors u_i written as the push on shape B (the reaction
// where the vertex belongs to A) the pair's elastic wrench on B is u'(D) times
//     G = sum g_i u_i,   T = sum g_i (x_i - c_B) x u_i   (about B's centre).
// For the sphere cap sum g_i = kappa ((k+1) S_k^2 - k S_{k-1} S_{k+1})/S_k^2
// = 1: |G| = 1 and the force is the law's, f(delta). For a flat face of N
// equally deep corners D = kappa delta and |G| = kappa: the face is
// kappa^{5/2} = 1.58 times stiffer than one Hertz point at the same depth.
//
// Why k = 4 (it was 2, kappa 4/3, until session 6). Any smooth maximum that
// ignores how many vertices there are must give shallow vertices a negative
// weight (adding a shallow vertex lowers a mean). Pressing the whole patch
// deeper by h changes D by h sum g_i, and one deep vertex among many shallow
// ones makes that sum vanish: with k = 2 already 7 vertices at a tenth of the
// deepest one's depth do (3 S2^2 = 2 S1 S3). The force then tends to zero
// while its torque does not: the line of action runs millimetres outside the
// grain and one step's torque kick multiplied an angular grain's energy up to
// 2e4-fold on landing (tests/lab/faceted_impact_test.cpp). With k = 4 the
// shallow weights fall as d_i^3: it takes ~30 vertices at 0.3 of the deepest
// depth, or ~300 at 0.1. (Also tried: falling back to the point contact of
// PD wherever the line of action misses either body's bounding sphere. It
// cut the gains of 10 m/s landings further, but the switch is a jump in the
// potential, and with it the golden run's consolidation never came to rest;
// not kept. docs/physics.md has the figures.)
//
// Mapping to one contact. The law is evaluated at depth D along n = G/|G| and
// its elastic force multiplied by gain = |G|; it acts at the point p of the
// wrench's line of action nearest the d^k-weighted centroid of the points
// halfway between each vertex and the other's surface,
// and the part of T along n (zero for a face on a plane) is returned as
// `twist`, a torque per unit u'(D). Damping and friction act at p.
#pragma once

#include "collision/contact_result.h"
#include "core/types.h"

#include <algorithm>
#include <cmath>

namespace grainlab {

// Accumulates the vertex depths of one pair and turns them into a contact.
class SoftDepth {
 public:
  // D = kappa S_{k+1}/S_k with k = kPower (see above); kappa = (k+2)/(k+1)
  // makes a finely tessellated sphere follow the law exactly.
  static constexpr int kPower = 4;
  static constexpr double kappa = (kPower + 2.0) / (kPower + 1.0);

  // Torques about c_b, B's centre (m).
  explicit SoftDepth(const Vec3& c_b) : c_(c_b) {}

  // A vertex at x (m) lying d > 0 (m) inside the other shape; u (unit) is the
  // push on B: A's outward face normal for a vertex of B, minus B's outward
  // face normal for a vertex of A (the reaction of the push on A); `mid` is
  // the point halfway between the vertex and the other's surface (m).
  void add(const Vec3& x, double d, const Vec3& u, const Vec3& mid) {
    const Vec3 s = x - c_;
    double dk1 = 1;  // d^{k-1}
    for (int j = 1; j < kPower; ++j) dk1 *= d;
    const double dk = dk1 * d, dk2 = dk * d;
    s1_ += d, sk_ += dk, sk1_ += dk2;
    const Vec3 m = s.cross(u);
    uk1_ += dk1 * u, uk_ += dk * u;
    mk1_ += dk1 * m, mk_ += dk * m;
    x1_ += d * s, xk_ += dk * (mid - c_);
    cov_ += d * (s * s.transpose());
  }

  // Any vertex inside?
  bool empty() const { return !(sk_ > 0); }
  // The smooth maximum D (m); 0 if empty.
  double depth() const { return empty() ? 0.0 : kappa * sk1_ / sk_; }

  // Writes depth D, normal, point, gain, twist and spread into r (touching);
  // false (r untouched) if no vertex is inside, if D is below the penetration
  // depth `pd` (m) of the point contact (the pair's potential is u(max(PD,
  // D)), continuous across the switch), or if the elastic force would not
  // push B away along `expect` (the point contact's normal): D is not
  // monotone in every d_i (see "Why k = 4" above).
  bool finish(ContactResult& r, double pd, const Vec3& expect) const {
    if (empty() || !(depth() > pd)) return false;
    const double inv = kappa / (sk_ * sk_);
    const Vec3 g = inv * ((kPower + 1) * sk_ * uk_ - kPower * sk1_ * uk1_);
    const Vec3 t = inv * ((kPower + 1) * sk_ * mk_ - kPower * sk1_ * mk1_);
    const double gain = g.norm();
    if (!(gain > 1e-9) || !(g.dot(expect) > 0.5 * gain)) return false;
    const Vec3 n = g / gain;
    // Line of action: (p - c) x g = t - n (n.t).
    const Vec3 p0 = c_ + g.cross(t) / (gain * gain);
    const Vec3 centroid = c_ + xk_ / sk_;
    r.touching = true;
    r.depth = depth();
    r.normal = n;
    r.point = p0 + (centroid - p0).dot(n) * n;
    r.gain = gain;
    r.twist = n.dot(t) * n;
    // Spread: depth-weighted tangential variance of the vertices about their mean.
    const Vec3 mean = x1_ / s1_;
    const Mat3 cov = cov_ / s1_ - mean * mean.transpose();
    r.spread = std::max(0.0, cov.trace() - n.dot(cov * n));
    return true;
  }

 private:
  Vec3 c_;
  double s1_ = 0, sk_ = 0, sk1_ = 0;
  Vec3 uk1_ = Vec3::Zero(), uk_ = Vec3::Zero(), mk1_ = Vec3::Zero(), mk_ = Vec3::Zero();
  Vec3 x1_ = Vec3::Zero(), xk_ = Vec3::Zero();
  Mat3 cov_ = Mat3::Zero();
};

}  // namespace grainlab
