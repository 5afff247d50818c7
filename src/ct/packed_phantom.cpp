#include "ct/packed_phantom.h"

#include "core/error.h"
#include "core/rng.h"
#include "ct/voxelize.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace grainlab::ct {

namespace {

constexpr double kGap = 2.0;   // voxels between grains of different clusters, and to the image faces
constexpr int kTries = 400;

// An ellipsoid with a ball cut out of its flank, in voxel-index coordinates.
struct Grain {
  Vec3 centre = Vec3::Zero();
  Mat3 axes = Mat3::Identity();  // columns: the long, intermediate and short axes
  Vec3 semi = Vec3::Ones();      // a, b, c
  Vec3 dent = Vec3::Zero();      // the cut ball's centre, in the grain's frame
  double dent_radius = 0;
  int power = 2;                 // superellipsoid exponent: 2 an ellipsoid, 3-4 flatter flanks

  // `grow` voxels added to every semi-axis (and the dent left out when > 0): a margin around the grain.
  bool inside(const Vec3& p, double grow = 0) const {
    const Vec3 l = axes.transpose() * (p - centre);
    const Vec3 s = semi.array() + grow;
    if (level(l, s) > 1) return false;
    return grow > 0 || (l - dent).squaredNorm() > dent_radius * dent_radius;
  }
  // sum |l_i / s_i|^p (p = 2, 3 or 4, by multiplication: this is the hot loop).
  double level(const Vec3& l, const Vec3& s) const {
    double sum = 0;
    for (int i = 0; i < 3; ++i) {
      const double x = std::abs(l[i] / s[i]), x2 = x * x;
      sum += power == 2 ? x2 : power == 3 ? x2 * x : x2 * x2;
    }
    return sum;
  }
  // Sure about a whole voxel (half-diagonal 0.87) around `p`: +1 inside, -1 outside, 0 unsure.
  // Along a ray from the centre, level^(1/p) = rho scales the surface, and a
  // point at rho > 1 is at least (rho - 1) c from it (c the smallest semi-axis, the inradius).
  int sure(const Vec3& p) const {
    const Vec3 l = axes.transpose() * (p - centre);
    const double rho = std::pow(level(l, semi), 1.0 / power), margin = 1.2 / semi.minCoeff();
    if (rho > 1 + margin) return -1;
    const double far = dent_radius + 1.2;
    return rho < 1 - margin && (l - dent).squaredNorm() > far * far ? 1 : 0;
  }
  // How deep `p` (inside) lies: along the ray from the centre, the surface is
  // at l / rho (rho = level^(1/p)), |l| (1 / rho - 1) away; from the dent,
  // |l - dent| - r_dent. The smaller of the two (a bound on the distance to the surface).
  double depth(const Vec3& p) const {
    const Vec3 l = axes.transpose() * (p - centre);
    const double rho = std::pow(level(l, semi), 1.0 / power);
    const double ray = rho > 0 ? l.norm() * (1 / rho - 1) : semi.minCoeff();
    return std::min(ray, (l - dent).norm() - dent_radius);
  }
  // Half-extents of an axis-aligned box around the (grown) grain: that of its turned bounding box.
  Vec3 half_box(double grow = 0) const {
    Vec3 h;
    for (int i = 0; i < 3; ++i) {
      double s = 0;
      for (int j = 0; j < 3; ++j) s += std::abs(axes(i, j)) * (semi[j] + grow);
      h[i] = s;
    }
    return h;
  }
};

// True when some point of a 0.5-voxel grid lies in both grains (`grow` added to `a`).
bool overlapping(const Grain& a, const Grain& b, double grow = 0) {
  const Vec3 ha = a.half_box(grow), hb = b.half_box();
  const Vec3 lo = (a.centre - ha).cwiseMax(b.centre - hb), hi = (a.centre + ha).cwiseMin(b.centre + hb);
  if ((lo.array() > hi.array()).any()) return false;
  for (double z = lo.z(); z <= hi.z(); z += 0.5) {
    for (double y = lo.y(); y <= hi.y(); y += 0.5) {
      for (double x = lo.x(); x <= hi.x(); x += 0.5) {
        const Vec3 p(x, y, z);
        if (b.inside(p) && a.inside(p, grow)) return true;
      }
    }
  }
  return false;
}

Mat3 turn(const Vec3& axis, double angle) { return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix(); }

Grain make_shape(const PackedPhantomSpec& spec, Rng& rng) {
  Grain g;
  const double b = 0.5 * spec.grain_size * rng.uniform(1 - spec.size_spread, 1 + spec.size_spread);
  // One draw a statement here and below: the order of a call's arguments, or
  // of an operator's operands, is the compiler's, and a seed must give the
  // same phantom whatever compiled it.
  const double flat = rng.uniform(0.75, 0.95), aspect = rng.uniform(spec.aspect_min, spec.aspect_max);
  g.semi = Vec3(b * aspect, b, b * flat);
  g.power = 2 + static_cast<int>(rng.uniform(0, 3));
  // The dent: on the flank (a direction across the long axis), 0.2-0.35 b deep.
  const double phi = rng.uniform(0, 2 * M_PI);
  const Vec3 dir(rng.uniform(-0.3, 0.3), std::cos(phi), std::sin(phi));
  const Vec3 n = dir.normalized();
  // Surface point along n: n / |n ./ semi|.
  const double t = std::pow((n.array() / g.semi.array()).abs().pow(g.power).sum(), -1.0 / g.power);
  g.dent_radius = b * rng.uniform(0.5, 0.8);
  const double depth = b * rng.uniform(0.2, 0.35);
  g.dent = n * (t + g.dent_radius - depth);
  return g;
}

}  // namespace

PackedPhantom make_packed_phantom(const PackedPhantomSpec& spec) {
  if (spec.grains < 1 || spec.size < 16 || !(spec.grain_size >= 6) || spec.samples < 1 ||
      !(spec.aspect_min >= 1 && spec.aspect_max >= spec.aspect_min)) {
    input_error("packed phantom: grains >= 1, size >= 16, grain size >= 6 voxels, samples >= 1 and "
                "1 <= aspect_min <= aspect_max are needed");
  }
  Rng rng(spec.seed);
  const double n = static_cast<double>(spec.size);
  std::vector<Grain> grains;
  std::vector<int> cluster_of;
  const std::array<int, 4> cluster_sizes{3, 2, 2, 1};
  int cluster = 0, left_in_cluster = 0;
  auto in_image = [&](const Grain& g) {
    const Vec3 h = g.half_box();
    return ((g.centre - h).array() >= kGap).all() && ((g.centre + h).array() <= n - 1 - kGap).all();
  };
  // Grains of other clusters keep kGap away; those of this one (but the partner) must not overlap.
  auto clear_of_others = [&](const Grain& g, int partner) {
    for (std::size_t q = 0; q < grains.size(); ++q) {
      const bool same = cluster_of[q] == cluster;
      if (static_cast<int>(q) != partner && overlapping(grains[q], g, same ? 0.0 : kGap)) return false;
    }
    return true;
  };
  int cluster_start = 0, restarts = 0;
  for (int k = 0; k < spec.grains; ++k) {
    const bool first = left_in_cluster == 0;
    if (first) {
      left_in_cluster = std::min(cluster_sizes[cluster++ % cluster_sizes.size()], spec.grains - k);
      cluster_start = k;
    }
    bool done = false;
    for (int attempt = 0; attempt < kTries && !done; ++attempt) {
      Grain g = make_shape(spec, rng);
      if (first) {
        g.axes = rng.rotation().toRotationMatrix();
        const Vec3 h = g.half_box();
        for (int i = 0; i < 3; ++i) g.centre[i] = rng.uniform(h[i] + kGap, std::max(h[i] + kGap, n - 1 - kGap - h[i]));
        if (!in_image(g) || !clear_of_others(g, -1)) continue;
      } else {
        const Grain& p = grains.back();
        Vec3 u;
        if (k % 2 == 1) {  // side by side: long axes parallel within 15 degrees
          const double roll_quarter = std::floor(rng.uniform(0, 4)), roll_off = rng.uniform(-0.15, 0.15);
          const double roll = roll_quarter * M_PI / 2 + roll_off;
          const double tilt = rng.uniform(0, 10 * M_PI / 180);
          const Vec3 tilt_axis = rng.unit_vector();
          g.axes = p.axes * turn(Vec3::UnitX(), roll) * turn(tilt_axis, tilt);
          const double phi_quarter = std::floor(rng.uniform(0, 4)), phi_off = rng.uniform(-0.25, 0.25);
          const double phi = phi_quarter * M_PI / 2 + phi_off;
          u = p.axes * Vec3(rng.uniform(-0.3, 0.3), std::cos(phi), std::sin(phi)).normalized();
        } else {
          g.axes = rng.rotation().toRotationMatrix();
          u = rng.unit_vector();
        }
        double lo = 0, hi = p.semi[0] + g.semi[0] + 1;  // overlapping at lo, apart at hi
        for (int it = 0; it < 14; ++it) {
          const double mid = 0.5 * (lo + hi);
          g.centre = p.centre + mid * u;
          (overlapping(p, g) ? lo : hi) = mid;
        }
        g.centre = p.centre + (hi - rng.uniform(-0.5, spec.press_max)) * u;
        if (!in_image(g) || !clear_of_others(g, static_cast<int>(grains.size()) - 1)) continue;
      }
      grains.push_back(g);
      cluster_of.push_back(cluster);
      done = true;
    }
    if (!done && !first && restarts < kTries) {
      // A follower found no room by its partner: place the whole cluster again.
      ++restarts;
      grains.resize(cluster_start);
      cluster_of.resize(cluster_start);
      --cluster;
      left_in_cluster = 0;
      k = cluster_start - 1;
      continue;
    }
    if (!done) {
      throw RunError(fmt::format("packed phantom: cannot place grain {} of {} in a {}^3 volume: use fewer grains "
                                 "or a larger size",
                                 k + 1, spec.grains, spec.size));
    }
    --left_in_cluster;
  }

  // Occupancy by sub-sampling. Where pressed grains overlap, a sample belongs
  // to the grain it lies deepest in (Grain::depth): the grains partition the
  // solid, as a segmentation must (a watershed on the distance map cuts the
  // overlap near its middle), so a grain's true volume is its share of the
  // solid, not its whole shape (the overlap counted twice). The truth is the
  // grain owning most of a voxel.
  PackedPhantom out;
  GreyVolume occ;
  occ.size = {spec.size, spec.size, spec.size};
  occ.spacing = Vec3::Constant(spec.voxel_size);
  occ.allocate(0.0f);
  out.truth.copy_grid(occ);
  out.truth.allocate(0);
  std::vector<float> best(occ.values.size(), 0.0f);
  const double voxel_volume = std::pow(spec.voxel_size, 3);
  const int s = spec.samples;
  for (std::size_t g = 0; g < grains.size(); ++g) {
    const Grain& gr = grains[g];
    const Vec3 h = gr.half_box();
    std::vector<std::size_t> near;  // grains whose boxes meet this one's
    for (std::size_t q = 0; q < grains.size(); ++q) {
      const Vec3 hq = grains[q].half_box();
      if (q != g && ((gr.centre - grains[q].centre).array().abs() <= (h + hq).array() + 1).all()) near.push_back(q);
    }
    // True when `p` (inside gr) lies deeper in gr than in every other grain holding it (ties: the lower index).
    auto owns = [&](const Vec3& p, const std::vector<std::size_t>& rivals) {
      const double d = gr.depth(p);
      for (std::size_t q : rivals) {
        if (!grains[q].inside(p)) continue;
        const double dq = grains[q].depth(p);
        if (dq > d || (dq == d && q < g)) return false;
      }
      return true;
    };
    Size3 lo, hi;
    for (int i = 0; i < 3; ++i) {
      lo[i] = std::max<std::int64_t>(0, static_cast<std::int64_t>(std::floor(gr.centre[i] - h[i])));
      hi[i] = std::min<std::int64_t>(spec.size - 1, static_cast<std::int64_t>(std::ceil(gr.centre[i] + h[i])));
    }
    double total = 0;
    std::vector<std::size_t> rivals;
    for (std::int64_t z = lo[2]; z <= hi[2]; ++z) {
      for (std::int64_t y = lo[1]; y <= hi[1]; ++y) {
        for (std::int64_t x = lo[0]; x <= hi[0]; ++x) {
          const Vec3 centre(x, y, z);
          int certain = gr.sure(centre);
          if (certain < 0) continue;
          rivals.clear();
          for (std::size_t q : near)
            if (grains[q].sure(centre) >= 0) rivals.push_back(q);
          if (!rivals.empty()) certain = 0;  // a voxel another grain may share is sampled
          int in = certain > 0 ? s * s * s : 0;
          for (int c = 0; c < s && !certain; ++c) {
            for (int b = 0; b < s; ++b) {
              for (int a = 0; a < s; ++a) {
                const Vec3 p(x + (a + 0.5) / s - 0.5, y + (b + 0.5) / s - 0.5, z + (c + 0.5) / s - 0.5);
                in += gr.inside(p) && (rivals.empty() || owns(p, rivals));
              }
            }
          }
          if (!in) continue;
          const float f = static_cast<float>(in) / (s * s * s);
          const std::size_t i = occ.index(x, y, z);
          occ.values[i] += f;  // the grains' shares of a voxel sum to its solid fraction (<= 1)
          total += f;
          if (f > best[i]) {
            best[i] = f;
            if (f >= 0.5f) out.truth.values[i] = static_cast<std::uint32_t>(g + 1);
          }
        }
      }
    }
    out.volumes.push_back(total * voxel_volume);
  }
  gaussian_blur(occ, spec.blur);
  constexpr float kPore = 10000, kSolid = 40000;
  for (float& v : occ.values) v = kPore + (kSolid - kPore) * v + static_cast<float>(spec.noise * (kSolid - kPore) * rng.normal());
  out.volume = std::move(occ);
  return out;
}

}  // namespace grainlab::ct
