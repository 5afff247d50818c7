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
#include <cstring>

namespace grainlab {

// Accumulates the pieces of edges inside the other shape of one pair and
// turns them into a contact.
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
  // The pieces are buffered and integrated four at a time (flush).
  void add_linear_piece(const Vec3& x0, const Vec3& x1, double d0, double d1, const Vec3& u) {
    if (!(d0 > 0) && !(d1 > 0)) return;
    if (count_ == kBuffer) flush();
    const Vec3 e = x1 - x0, s0 = x0 - c_;
    const int i = count_++;
    for (int j = 0; j < 3; ++j) s0_[j][i] = s0[j], e_[j][i] = e[j], u_[j][i] = u[j];
    d0_[i] = d0, d1_[i] = d1, length_[i] = e.norm();
  }

  // Nothing inside?
  bool empty() {
    flush();
    return !(sk_ > 0);
  }
  // The smooth maximum D (m); 0 if empty.
  double depth() { return empty() ? 0.0 : kappa * sk1_ / sk_; }

  // Writes depth D, normal, point, gain, twist and spread into r (touching);
  // false (r untouched) if nothing is inside, or if the elastic force would
  // not push B away along `expect` (the penetration normal of GJK/EPA): D is
  // not monotone in every d_i (see "Why k = 4" above). Then the caller keeps
  // its point contact: a jump in the potential, so it must stay rare
  // (bench_contact_energy counts point contacts).
  bool finish(ContactResult& r, const Vec3& expect) {
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
  // Four pieces at a time (GCC/Clang vector extension: AVX on x86-64-v3).
  using Lanes = double __attribute__((vector_size(32)));
  static constexpr int kLanes = 4, kBuffer = 64;
  static Lanes lanes(double x) { return Lanes{x, x, x, x}; }
  static Lanes at(const double* p) {  // an unaligned load (memcpy: no alignment or aliasing assumed)
    Lanes v;
    std::memcpy(&v, p, sizeof v);
    return v;
  }
  static double sum(Lanes v) { return (v[0] + v[1]) + (v[2] + v[3]); }

  // Integrates the buffered pieces into the sums: the positive part of
  // each piece, t in [a, b] (fractions of the piece), by its three Gauss
  // nodes (see add_linear_piece). Lanes past count_ hold a piece of depth 0
  // and length 0, which adds nothing.
  void flush() {
    if (count_ == 0) return;
    const int padded = (count_ + kLanes - 1) / kLanes * kLanes;
    for (int i = count_; i < padded; ++i) {
      for (int j = 0; j < 3; ++j) s0_[j][i] = e_[j][i] = u_[j][i] = 0;
      d0_[i] = d1_[i] = length_[i] = 0;
    }
    static constexpr double node[3] = {0.5 - 0.5 * 0.7745966692414834, 0.5, 0.5 + 0.5 * 0.7745966692414834};
    static constexpr double weight[3] = {5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0};
    static_assert(kPower == 4, "the node loop below writes d^{k-1} = d^3 out");
    const Lanes zero = lanes(0), one = lanes(1);
    Lanes s1 = zero, sk = zero, sk1 = zero, uk1[3], uk[3], mk1[3], mk[3], xk[3], x1[3], cov[6];
    for (int j = 0; j < 3; ++j) uk1[j] = uk[j] = mk1[j] = mk[j] = xk[j] = x1[j] = zero;
    for (Lanes& c : cov) c = zero;
    for (int i = 0; i < padded; i += kLanes) {
      const Lanes d0 = at(d0_ + i), d1 = at(d1_ + i), den = d0 - d1;
      const Lanes root = d0 / (den == zero ? one : den);  // where the depth is 0
      const Lanes a = d0 > zero ? zero : root, b = d1 > zero ? one : root;
      // Moments sum w f t^i: f = d (i = 0..2), d^{k-1}, d^k (i = 0, 1),
      // d^{k+1}; Gauss weights first, then times the length. d > 0 inside
      // the positive part; the max only guards rounding at its ends.
      Lanes m10 = zero, m11 = zero, m12 = zero, k10 = zero, k11 = zero, k0 = zero, k01 = zero, k2 = zero;
      for (int g = 0; g < 3; ++g) {
        const Lanes t = a + (b - a) * node[g];
        Lanes d = d0 + (d1 - d0) * t;
        d = d > zero ? d : zero;
        const Lanes wd = weight[g] * d, dk1 = wd * d * d, dk = dk1 * d;
        m10 += wd, m11 += wd * t, m12 += wd * t * t;
        k10 += dk1, k11 += dk1 * t;
        k0 += dk, k01 += dk * t;
        k2 += dk * d;
      }
      const Lanes length = at(length_ + i) * (b - a);
      m10 *= length, m11 *= length, m12 *= length, k10 *= length, k11 *= length;
      k0 *= length, k01 *= length, k2 *= length;
      const Lanes s0[3] = {at(s0_[0] + i), at(s0_[1] + i), at(s0_[2] + i)};
      const Lanes e[3] = {at(e_[0] + i), at(e_[1] + i), at(e_[2] + i)};
      const Lanes u[3] = {at(u_[0] + i), at(u_[1] + i), at(u_[2] + i)};
      s1 += m10, sk += k0, sk1 += k2;
      Lanes p1[3], pk[3], first[3], second[3];  // moments of position: d^{k-1}, d^k, d; and sum w d t s
      for (int j = 0; j < 3; ++j) {
        uk1[j] += k10 * u[j], uk[j] += k0 * u[j];
        p1[j] = k10 * s0[j] + k11 * e[j];
        pk[j] = k0 * s0[j] + k01 * e[j];
        first[j] = m10 * s0[j] + m11 * e[j];
        second[j] = m11 * s0[j] + m12 * e[j];
        xk[j] += pk[j], x1[j] += first[j];
      }
      for (int j = 0; j < 3; ++j) {  // the crosses with u
        const int y = (j + 1) % 3, z = (j + 2) % 3;
        mk1[j] += p1[y] * u[z] - p1[z] * u[y];
        mk[j] += pk[y] * u[z] - pk[z] * u[y];
      }
      // sum w d s s^T with s = s0 + t e is s0 first^T + e second^T
      // (symmetric): its upper triangle, row by row.
      int c = 0;
      for (int r = 0; r < 3; ++r)
        for (int q = r; q < 3; ++q) cov[c++] += s0[r] * first[q] + e[r] * second[q];
    }
    s1_ += sum(s1), sk_ += sum(sk), sk1_ += sum(sk1);
    int c = 0;
    for (int j = 0; j < 3; ++j) {
      uk1_[j] += sum(uk1[j]), uk_[j] += sum(uk[j]), mk1_[j] += sum(mk1[j]), mk_[j] += sum(mk[j]);
      xk_[j] += sum(xk[j]), x1_[j] += sum(x1[j]);
      for (int q = j; q < 3; ++q) cov_(j, q) += sum(cov[c++]);
    }
    count_ = 0;
  }

  Vec3 c_;
  double s1_ = 0, sk_ = 0, sk1_ = 0;
  Vec3 uk1_ = Vec3::Zero(), uk_ = Vec3::Zero(), mk1_ = Vec3::Zero(), mk_ = Vec3::Zero();
  Vec3 x1_ = Vec3::Zero(), xk_ = Vec3::Zero();
  Mat3 cov_ = Mat3::Zero();  // its upper triangle
  // The buffered pieces, by component: start relative to c_, edge vector,
  // push direction, end depths, length.
  int count_ = 0;
  double s0_[3][kBuffer], e_[3][kBuffer], u_[3][kBuffer], d0_[kBuffer], d1_[kBuffer], length_[kBuffer];
};

}  // namespace grainlab
