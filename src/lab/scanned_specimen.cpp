// Specimens from a segmented scan (see scanned_specimen.h).
#include "lab/scanned_specimen.h"

#include "core/error.h"
#include "geometry/mass_properties.h"
#include "grains/scanned_grains.h"
#include "lab/grain_library.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace grainlab {

Specimen place_scanned_specimen(World& w, const LabSpec& spec, Index grain_material) {
  const ScannedGrains scan = read_scanned_grains(spec.grains.scan, spec.grains.scan_border == "keep");
  Specimen sp;
  const std::vector<Index> shapes =
      add_mesh_shapes(w.model, scan.meshes, scan.names, false, spec.grains.representation,
                      spec.numerics.threads, &sp.representation);
  Vec3 lo = Vec3::Constant(INFINITY), hi = -lo;
  std::vector<MassProperties> mp;
  for (const TriMesh& m : scan.meshes) {
    mp.push_back(mass_properties(m));
    for (const Vec3& v : m.vertices) {
      lo = lo.cwiseMin(v);
      hi = hi.cwiseMax(v);
    }
    sp.solid_volume += mp.back().volume;
  }
  const int n = static_cast<int>(scan.meshes.size());
  sp.mean_diameter = std::cbrt(6.0 * sp.solid_volume / n / std::numbers::pi);
  const Vec3 centre = 0.5 * (lo + hi);
  const Index first = static_cast<Index>(w.model.bodies.size());

  for (int k = 0; k < n; ++k) w.add_body(shapes[k], grain_material, 1.0, Vec3::Zero(), Quat(mp[k].principal_axes));
  // The probe steps below find contacts; they must leave no trace in the step count or the clock.
  const auto step0 = w.state.step;
  const double time0 = w.state.time;
  const Vec3 gravity = w.model.gravity;
  w.model.gravity = Vec3::Zero();
  double spread = 0;
  for (double f : kScanSpreads) {
    const Vec3 extent = f * (hi - lo);
    if (extent.x() > spec.box.length || extent.y() > spec.box.width)
      input_error("grains.scan = {}: its {} grains span {:.3f} x {:.3f} mm (x, y), more than the box's {:.3f} x "
                  "{:.3f} mm: set box.length >= {:.4g} and box.width >= {:.4g} (m)",
                  spec.grains.scan, n, extent.x() * 1e3, extent.y() * 1e3, spec.box.length * 1e3,
                  spec.box.width * 1e3, extent.x() * 1.01, extent.y() * 1.01);
    // Centred on x = y = 0, the lowest point 1 % of a diameter above the floor (z = 0).
    const Vec3 shift(0, 0, 0.5 * extent.z() + 0.01 * sp.mean_diameter);
    for (int k = 0; k < n; ++k) {
      BodyState& b = w.state.bodies[first + k];
      b.x = shift + f * (mp[k].centroid - centre);
      b.q = Quat(mp[k].principal_axes);
      b.v = b.w = Vec3::Zero();
    }
    // The deepest overlap at these positions (a step of no duration finds the contacts).
    w.step(1e-30);
    double deepest = 0;
    for (const Contact& c : w.state.contacts) deepest = std::max(deepest, c.geo.depth);
    sp.fill_top = f * (hi.z() - lo.z()) + 0.01 * sp.mean_diameter;
    if (deepest <= kScanOverlap * sp.mean_diameter) {
      spread = f;
      break;
    }
    if (f == kScanSpreads[std::size(kScanSpreads) - 1])
      input_error("grains.scan = {}: scanned grains still overlap by {:.3g} um (more than {:.3g} of a diameter) "
                  "with their positions spread by {}: the segmentation merged or cut grains badly; check it "
                  "with `grainlab grains stats` and ParaView",
                  spec.grains.scan, deepest * 1e6, kScanOverlap, f);
  }
  w.model.gravity = gravity;
  w.state.step = step0;
  w.state.time = time0;
  for (int k = 0; k < n; ++k) {
    w.state.bodies[first + k].v = w.state.bodies[first + k].w = Vec3::Zero();
    sp.mean_mass += w.model.bodies[first + k].gravity_mass / n;
  }
  sp.scan.grains = n;
  sp.scan.border_dropped = scan.border_dropped;
  sp.scan.spread = spread;
  sp.scan.void_ratio = (hi - lo).prod() / sp.solid_volume - 1;
  return sp;
}

}  // namespace grainlab
