// Concave grains collided as convex pieces (convex_decomposition.h) against
// their convex hulls: what the decomposition costs and gains per shape, what
// a touching pair costs, and the force at a seam between two pieces. Not a
// test: it prints figures.
//
//   build/bench_concave_grains [--faces F] [--seeds S] [--pairs P] [--repeat K]
//
// 1. Per shape (sub-angular preset, each convexity, S seeds; medians):
//    decomposition time, pieces, the volume the hull and the pieces fill
//    in beyond the grain (% of its volume), and the collision data's memory.
// 2. Per touching pair (two grains of one convexity, random orientations,
//    brought together along a random direction until the pieces touch, then
//    pressed 0.5 % of the radius): narrowphase time per call, one thread;
//    the hull pair keeps its warm cache as in a run; the pieces both cold
//    (each piece pair from scratch, as before session 17) and with their
//    piece pairs' caches kept as in a run (CandidatePair::pieces).
// 3. A seam: a sphere pressed 10 um into the flat underside of a U-shaped
//    grain, moved across the seam where two pieces meet; the force over the
//    hull's (exact on that face). Two pieces each push with the full depth
//    near the seam.
#include "bench_args.h"
#include "collision/dispatch.h"
#include "core/rng.h"
#include "core/timer.h"
#include "dynamics/world.h"
#include "geometry/convex_decomposition.h"
#include "geometry/convex_hull.h"
#include "geometry/mass_properties.h"
#include "geometry/primitives.h"
#include "grains/generator.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

using namespace grainlab;

namespace {

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0 : v[v.size() / 2];
}

struct PairCost {
  double hull_us = 0, pieces_us = 0, kept_us = 0, pieces_touching = 0;
};

// Two grains of `mesh_a`, `mesh_b` in both representations; P touching pairs timed.
PairCost time_pairs(const TriMesh& mesh_a, const TriMesh& mesh_b, int pairs, int repeat, Rng& rng) {
  World w;
  w.model.gravity = Vec3::Zero();
  const Index hull_a = w.model.add_mesh_shape(mesh_a, "a"), hull_b = w.model.add_mesh_shape(mesh_b, "b");
  const Index cc_a = w.model.add_concave_shape(mesh_a, decompose_convex(mesh_a), "a pieces");
  const Index cc_b = w.model.add_concave_shape(mesh_b, decompose_convex(mesh_b), "b pieces");
  const Index ha = w.add_body(hull_a, 0, 1.0, Vec3::Zero()), hb = w.add_body(hull_b, 0, 1.0, Vec3::Zero());
  const Index ca = w.add_body(cc_a, 0, 1.0, Vec3::Zero()), cb = w.add_body(cc_b, 0, 1.0, Vec3::Zero());
  const double reach = w.model.shapes[cc_a].bounding_radius + w.model.shapes[cc_b].bounding_radius;
  const double press = 0.005 * w.model.shapes[cc_a].equivalent_radius;
  std::vector<double> hull_t, piece_t, kept_t;
  double touching = 0;
  SubContact out[kMaxSubContacts];
  for (int p = 0; p < pairs; ++p) {
    const Quat qa = rng.rotation(), qb = rng.rotation();
    const Vec3 u = rng.unit_vector();
    for (Index i : {ha, ca}) w.state.bodies[i].q = qa;
    for (Index i : {hb, cb}) w.state.bodies[i].q = qb;
    w.step(1e-30);  // refresh the posed rotations
    // Bisect the distance along u at which the pieces touch.
    double lo = 0, hi = reach;
    for (int it = 0; it < 50; ++it) {
      const double mid = 0.5 * (lo + hi);
      w.state.bodies[cb].x = mid * u;
      PairCache cold;
      (collide_shapes(w.posed_body(ca), w.posed_body(cb), cold, out) > 0 ? lo : hi) = mid;
    }
    for (Index i : {hb, cb}) w.state.bodies[i].x = (lo - press) * u;
    PairCache hull_cache, piece_cache;
    collide_shapes(w.posed_body(ha), w.posed_body(hb), hull_cache, out);  // warm it
    Stopwatch t;
    for (int k = 0; k < repeat; ++k) collide_shapes(w.posed_body(ha), w.posed_body(hb), hull_cache, out);
    hull_t.push_back(t.seconds() / repeat);
    Stopwatch t2;
    int n = 0;
    for (int k = 0; k < repeat; ++k) n = collide_shapes(w.posed_body(ca), w.posed_body(cb), piece_cache, out);
    piece_t.push_back(t2.seconds() / repeat);
    touching += n;
    std::vector<PairCache> pieces(static_cast<std::size_t>(piece_cache_count(w.posed_body(ca), w.posed_body(cb))));
    PairCache kept;
    collide_shapes(w.posed_body(ca), w.posed_body(cb), kept, out, pieces.data());  // warm them
    Stopwatch t3;
    for (int k = 0; k < repeat; ++k) collide_shapes(w.posed_body(ca), w.posed_body(cb), kept, out, pieces.data());
    kept_t.push_back(t3.seconds() / repeat);
  }
  return {1e6 * median(hull_t), 1e6 * median(piece_t), 1e6 * median(kept_t), touching / pairs};
}

// A U open towards +y, 6 x 3 x 2 mm, bars 1 mm thick.
TriMesh u_grain() {
  TriMesh u = prism_mesh({{-3, 0}, {3, 0}, {3, 3}, {2, 3}, {2, 1}, {-2, 1}, {-2, 3}, {-3, 3}}, 1.0);
  for (Vec3& v : u.vertices) v *= 1e-3;
  return u;
}

// A sphere pressed 10 um into the U's underside (y = 0) at x: the force on it.
struct SeamProbe {
  World w;
  Index ball = 0;
  explicit SeamProbe(bool pieces) {
    const TriMesh u = u_grain();
    const MassProperties mp = mass_properties(u);
    w.model.gravity = Vec3::Zero();
    Material m;
    m.youngs_modulus = 1e7;
    const Index mat = w.model.add_material(m);
    const Index shape = pieces ? w.model.add_concave_shape(u, decompose_convex(u), "pieces")
                               : w.model.add_mesh_shape(u, "hull");
    w.add_body(shape, mat, 1.0, mp.centroid, Quat(mp.principal_axes));
    ball = w.add_body(w.model.add_sphere_shape(0.5e-3), mat, 1.0, Vec3::Zero());
  }
  double force_at(double x) {
    w.state.bodies[0].v = w.state.bodies[0].w = Vec3::Zero();
    w.state.bodies[ball].x = Vec3(x, -0.5e-3 + 10e-6, 0);
    w.state.bodies[ball].v = Vec3::Zero();
    w.step(1e-12);
    Vec3 f = Vec3::Zero();
    for (const Contact& c : w.state.contacts) f += c.force;
    return f.norm();
  }
};

}  // namespace

int main(int argc, char** argv) {
  grainlab::bench::check_args(argc, argv, "[--faces F] [--seeds S] [--pairs P] [--repeat K]",
                              {"--faces", "--seeds", "--pairs", "--repeat"});
  std::vector<int> faces_list{200, 2000};
  int seeds = 3, pairs = 40, repeat = 50;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--faces")) faces_list = {std::stoi(argv[i + 1])};
    else if (!std::strcmp(argv[i], "--seeds")) seeds = std::stoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--pairs")) pairs = std::stoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--repeat")) repeat = std::stoi(argv[i + 1]);
  }
  fmt::print("concave grains: convex pieces against the convex hull (sub-angular preset; medians over {} seeds, "
             "{} touching pairs)\n\n",
             seeds, pairs);
  fmt::print("{:>5} {:>9} | {:>8} {:>6} {:>11} {:>13} {:>9} {:>11} | {:>9} {:>10} {:>10} {:>8}\n", "faces",
             "convexity", "decomp s", "pieces", "hull fill %", "pieces fill %", "hull KB", "pieces KB", "hull us",
             "cold us", "kept us", "touching");
  for (int faces : faces_list)
    for (double c : {1.0, 0.95, 0.9, 0.85, 0.8}) {
      std::vector<double> secs, pieces, hull_fill, piece_fill, hull_kb, piece_kb;
      std::vector<TriMesh> meshes;
      for (int s = 0; s < seeds; ++s) {
        GeneratorSpec g = preset_spec(GrainPreset::SubAngular);
        g.faces = faces;
        g.convexity = c;
        Rng rng(100 + s);
        meshes.push_back(generate_grain(g, rng));
        Stopwatch t;
        const ConvexDecomposition d = decompose_convex(meshes.back());
        secs.push_back(t.seconds());
        pieces.push_back(static_cast<double>(d.pieces.size()));
        hull_fill.push_back(100 * d.hull_excess());
        piece_fill.push_back(100 * d.excess());
        Model m;
        const Shape& hs = m.shapes[m.add_mesh_shape(meshes.back(), "h")];
        hull_kb.push_back(hs.geometry_as<ConvexPolytope>().memory_bytes() / 1024.0);
        const Shape& cs = m.shapes[m.add_concave_shape(meshes.back(), d, "c")];
        double kb = 0;
        for (const CompoundPiece& p : cs.geometry_as<CompoundShape>().pieces) kb += p.hull.memory_bytes() / 1024.0;
        piece_kb.push_back(kb);
      }
      Rng rng(7);
      const PairCost cost = time_pairs(meshes[0], meshes[seeds > 1 ? 1 : 0], pairs, repeat, rng);
      fmt::print(
          "{:>5} {:>9.2f} | {:>8.2f} {:>6.0f} {:>11.1f} {:>13.1f} {:>9.1f} {:>11.1f} | {:>9.2f} {:>10.2f} {:>10.2f} "
          "{:>8.2f}\n",
          faces, c, median(secs), median(pieces), median(hull_fill), median(piece_fill), median(hull_kb),
          median(piece_kb), cost.hull_us, cost.pieces_us, cost.kept_us, cost.pieces_touching);
    }
  fmt::print("\nseams: a sphere (r 0.5 mm) pressed 10 um into the flat underside of a U grain (6 x 3 x 2 mm, "
             "{} pieces), force as pieces / as hull, at x from -2.9 to 2.9 mm every 0.01 mm:\n",
             decompose_convex(u_grain()).pieces.size());
  double worst = 0, worst_x = 0, lowest = 1e9;
  int off = 0, n = 0;
  SeamProbe hull(false), pieces(true);
  for (int i = -290; i <= 290; ++i, ++n) {
    const double r = pieces.force_at(i * 1e-5) / hull.force_at(i * 1e-5);
    if (r > worst) worst = r, worst_x = i * 1e-2;
    lowest = std::min(lowest, r);
    off += std::abs(r - 1) > 0.05;
  }
  fmt::print("  largest {:.3f} (at x {:.2f} mm), smallest {:.3f}; off by more than 5 % at {} of {} positions\n", worst,
             worst_x, lowest, off, n);
  return 0;
}
