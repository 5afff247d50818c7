// The conservative contact of faceted shapes: one potential per pair, a
// function of the depths of the points of its edges lying inside the other shape.
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
// The measure: the edges inside the other shape (session 8; vertices
// before). A point x of an edge of either shape lying inside the other has
// depth d(x) > 0, its distance inside the other's nearest face plane (or below
// a wall): along an edge the lower envelope of the face planes' distances,
// piecewise linear, 0 where the edge enters. The pair's potential is U = u(D),
// u the contact law's elastic energy, with the smooth maximum
//     D = kappa S_{k+1} / S_k,   S_j = sum over edges of the integral of d^j ds,
//     k = 4,   kappa = (k+2)/(k+1) = 6/5.
// Every overlap of two convex polytopes has an edge of one inside the other
// (a vertex of A n B is a vertex of A or B, or where an edge of one crosses a
// face of the other), so D > 0 whenever they overlap, and no other depth (no
// penetration depth PD) enters the potential. D is continuous and C1 in the
// poses: an integral of a continuous, piecewise linear depth whose pieces
// meet where their integrands agree and end where the depth is 0. Why not
// vertices alone, as before: two edges crossing have no vertex inside, so
// such a contact needed PD, and u(max(PD, D)) kinked where D = PD. PD itself
// has V-shaped kinks as the pair moves (the deepest feature switches): the
// energy audit bench_contact_energy measured a frictionless 40-face bed,
// run undamped, gaining 1.0e-6 J per 1000 steps (5 % of its elastic energy),
// four fifths through the PD contacts; with the edge measure -2e-10, like a
// bed of spheres (3e-9).
// kappa makes a finely tessellated sphere follow the law: with edges evenly
// spread over a cap of depth delta (equal length per area), d = delta -
// rho^2/(2R), S_j = c 2 pi R delta^{j+1}/(j+1), so D = kappa (k+1)/(k+2)
// delta = delta. Its edges are chords, inside the sphere by up to s^2/(8R)
// for edge length s: against the volume-equivalent sphere (the engine's
// Hertz radius) that sag is what makes the tessellation converge.
// A corner pressed into a face: D = kappa (k+1)/(k+2) d = d, its depth. A
// flat face of equally deep edges: D = kappa delta, |G| = kappa (below): the
// face is kappa^{5/2} = 1.58 times stiffer than one Hertz point.
// The integral along a straight piece where one plane is nearest is exact by
// 3-point Gauss-Legendre (add_linear_piece): each node a point of weight
// length * w_g with its depth, as a vertex was.
//
// The forces (exact gradient). For the points i (Gauss nodes, weight w_i),
// dD/dd_i = w_i kappa d_i^{k-1} ((k+1) d_i S_k - k S_{k+1}) / S_k^2 = g_i.
// Point i carries u'(D) g_i along u_i, the outward
// normal of the other shape's face that is nearest (pushing the point out),
// so with the unit vectors u_i written as the push on shape B (the reaction
// where the point belongs to A) the pair's elastic wrench on B is u'(D) times
//     G = sum g_i u_i,   T = sum g_i (x_i - c_B) x u_i   (about B's centre).
// (The depth's changes at the pieces' ends add nothing: there the integrand
// is continuous or zero.) For the sphere cap sum g_i = kappa ((k+1) S_k^2 -
// k S_{k-1} S_{k+1})/S_k^2 = 1: |G| = 1 and the force is the law's, f(delta).
//
// Why k = 4 (it was 2, kappa 4/3, until session 6). Any smooth maximum that
// ignores how much is inside must give shallow points a negative
// weight (adding a shallow point lowers a mean). Pressing the whole patch
// deeper by h changes D by h sum g_i, and one deep point among many shallow
// ones makes that sum vanish: with k = 2 already 7 vertices at a tenth of the
// deepest one's depth did (3 S2^2 = 2 S1 S3). The force then tends to zero
// while its torque does not: the line of action runs millimetres outside the
// grain and one step's torque kick multiplied an angular grain's energy up to
// 2e4-fold on landing (tests/lab/faceted_impact_test.cpp). With k = 4 the
// shallow weights fall as d_i^3. (Also tried: falling back to the point
// contact of PD wherever the line of action misses either body's bounding
// sphere. The switch is a jump in the potential, and with it the golden
// run's consolidation never came to rest; not kept. docs/physics.md has the
// figures.)
//
// Mapping to one contact. The law is evaluated at depth D along n = G/|G| and
// its elastic force multiplied by gain = |G|; it acts at the point p of the
// wrench's line of action nearest the d^k-weighted centroid of the points,
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

  // A straight piece of an edge from x0 to x1 (m) whose depth varies
  // linearly from d0 to d1 (m) inside a face of the other shape, pushed along
  // u (that face's outward normal for a piece of B, minus it for a piece of
  // A). Its part with positive depth enters by 3-point Gauss-Legendre: each
  // node x_g a point of weight w_g = length * (Gauss weight) and depth d_g,
  // contributing w_g d_g^j to S_j, its g-term along u at x_g to G and T, and
  // x_g itself to the centroid. Exact: the integrands are
  // polynomials of degree k + 1 = 5 at most along a piece (d^{k+1}, d^k times
  // a position), and 3 nodes integrate degree 5. Along the piece
  // x = x0 + t (x1 - x0), so every vector sum is (sum of w f) (x0 - c) +
  // (sum of w f t) (x1 - x0): the nodes only need scalar moments.
  void add_linear_piece(const Vec3& x0, const Vec3& x1, double d0, double d1, const Vec3& u) {
    double a = 0, b = 1;  // the positive part, as fractions of the piece
    if (!(d0 > 0) && !(d1 > 0)) return;
    if (!(d0 > 0)) a = d0 / (d0 - d1);
    else if (!(d1 > 0)) b = d0 / (d0 - d1);
    const Vec3 e = x1 - x0, s0 = x0 - c_;
    const double length = e.norm() * (b - a);
    static constexpr double node[3] = {0.5 - 0.5 * 0.7745966692414834, 0.5, 0.5 + 0.5 * 0.7745966692414834};
    static constexpr double weight[3] = {5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0};
    // Moments sum w f t^i: f = d (i = 0..2), d^{k-1}, d^k (i = 0, 1), d^{k+1}.
    double m1[3] = {0, 0, 0}, mk1[2] = {0, 0}, mk[2] = {0, 0}, mk2 = 0;
    for (int g = 0; g < 3; ++g) {
      const double t = a + (b - a) * node[g];
      const double d = d0 + (d1 - d0) * t;
      if (!(d > 0)) continue;
      const double w = length * weight[g];
      double dk1 = w;  // w d^{k-1}
      for (int j = 1; j < kPower; ++j) dk1 *= d;
      const double dk = dk1 * d, wd = w * d;
      m1[0] += wd, m1[1] += wd * t, m1[2] += wd * t * t;
      mk1[0] += dk1, mk1[1] += dk1 * t;
      mk[0] += dk, mk[1] += dk * t;
      mk2 += dk * d;
    }
    s1_ += m1[0], sk_ += mk[0], sk1_ += mk2;
    uk1_ += mk1[0] * u, uk_ += mk[0] * u;
    mk1_ += (mk1[0] * s0 + mk1[1] * e).cross(u);
    const Vec3 moment = mk[0] * s0 + mk[1] * e;  // sum w d^k (x - c)
    mk_ += moment.cross(u);
    xk_ += moment;
    x1_ += m1[0] * s0 + m1[1] * e;
    // sum w d s s^T with s = s0 + t e: symmetric, its upper triangle.
    for (int i = 0; i < 3; ++i)
      for (int j = i; j < 3; ++j)
        cov_(i, j) += m1[0] * s0[i] * s0[j] + m1[1] * (s0[i] * e[j] + e[i] * s0[j]) + m1[2] * e[i] * e[j];
  }

  // Nothing inside?
  bool empty() const { return !(sk_ > 0); }
  // The smooth maximum D (m); 0 if empty.
  double depth() const { return empty() ? 0.0 : kappa * sk1_ / sk_; }

  // Writes depth D, normal, point, gain, twist and spread into r (touching);
  // false (r untouched) if nothing is inside, or if the elastic force would
  // not push B away along `expect` (the penetration normal of GJK/EPA): D is
  // not monotone in every d_i (see "Why k = 4" above). Then the caller keeps
  // its point contact: a jump in the potential, so it must stay rare
  // (bench_contact_energy counts point contacts).
  bool finish(ContactResult& r, const Vec3& expect) const {
    if (empty()) return false;
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
    // Spread: depth-weighted tangential variance of the points about their mean.
    const Vec3 mean = x1_ / s1_;
    const Mat3 upper = cov_.triangularView<Eigen::Upper>();
    const Mat3 cov = (upper + upper.transpose() - Mat3(upper.diagonal().asDiagonal())) / s1_ - mean * mean.transpose();
    r.spread = std::max(0.0, cov.trace() - n.dot(cov * n));
    return true;
  }

 private:
  Vec3 c_;
  double s1_ = 0, sk_ = 0, sk1_ = 0;
  Vec3 uk1_ = Vec3::Zero(), uk_ = Vec3::Zero(), mk1_ = Vec3::Zero(), mk_ = Vec3::Zero();
  Vec3 x1_ = Vec3::Zero(), xk_ = Vec3::Zero();
  Mat3 cov_ = Mat3::Zero();  // its upper triangle
};

}  // namespace grainlab
