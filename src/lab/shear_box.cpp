// The direct shear box's walls (layout in shear_box.h).
#include "lab/shear_box.h"

#include <string>

namespace grainlab {

void build_shear_box(World& w, const BoxSpec& box, double fill_top, Index material) {
  const double L = box.length, W = box.width, H = box.height, gap = box.gap;
  const double t = kShearBoxSlab;
  w.add_plane(Vec3::Zero(), Vec3::UnitZ(), material, "floor");
  const double lower_top = 0.5 * H - 0.5 * gap, top = fill_top + t;
  for (int half = 0; half < 2; ++half) {
    // The upper half, gap closed: from lower_top to top - gap (its height
    // once open: from H/2 + gap/2 to top).
    const double z0 = half == 0 ? -t : lower_top, z1 = half == 0 ? lower_top : top - gap;
    const double zc = 0.5 * (z0 + z1), hz = 0.5 * (z1 - z0);
    const std::string name = half == 0 ? "lower" : "upper";
    w.add_box_wall(Vec3(-0.5 * L - 0.5 * t, 0, zc), Vec3(0.5 * t, 0.5 * W + t, hz), Quat::Identity(), material,
                   name + "-x");
    w.add_box_wall(Vec3(0.5 * L + 0.5 * t, 0, zc), Vec3(0.5 * t, 0.5 * W + t, hz), Quat::Identity(), material,
                   name + "+x");
    w.add_box_wall(Vec3(0, -0.5 * W - 0.5 * t, zc), Vec3(0.5 * L + t, 0.5 * t, hz), Quat::Identity(), material,
                   name + "-y");
    w.add_box_wall(Vec3(0, 0.5 * W + 0.5 * t, zc), Vec3(0.5 * L + t, 0.5 * t, hz), Quat::Identity(), material,
                   name + "+y");
  }
  w.add_plane(Vec3(0, 0, top - 0.5 * t), -Vec3::UnitZ(), material, "cap");
}

void open_shear_box_gap(World& w, const BoxSpec& box) {
  const double upper_bottom = 0.5 * box.height + 0.5 * box.gap;
  for (Index r = UpperXm; r <= UpperYp; ++r) w.state.walls[r].x.z() = upper_bottom + w.model.walls[r].half.z();
}

Index grain_outside_shear_box(const World& w) {
  const auto& walls = w.state.walls;
  // Outer faces of the side slabs: the lower and upper halves' extremes
  // (the upper half has moved along +x in the shear).
  const double t = kShearBoxSlab;
  const double x_lo = std::min(walls[LowerXm].x.x(), walls[UpperXm].x.x()) - 0.5 * t;
  const double x_hi = std::max(walls[LowerXp].x.x(), walls[UpperXp].x.x()) + 0.5 * t;
  const double y_lo = walls[LowerYm].x.y() - 0.5 * t, y_hi = walls[LowerYp].x.y() + 0.5 * t;
  const double z_lo = walls[Floor].x.z() - t, z_hi = walls[Cap].x.z() + t;
  for (std::size_t i = 0; i < w.state.bodies.size(); ++i) {
    const Vec3& x = w.state.bodies[i].x;
    if (!(x.x() >= x_lo && x.x() <= x_hi && x.y() >= y_lo && x.y() <= y_hi && x.z() >= z_lo && x.z() <= z_hi))
      return static_cast<Index>(i);
  }
  return -1;
}

}  // namespace grainlab
