// The direct shear box's walls (layout in shear_box.h).
#include "lab/shear_box.h"

#include <string>

namespace grainlab {

void build_shear_box(World& w, const BoxSpec& box, double fill_top, Index material) {
  const double L = box.length, W = box.width, H = box.height, gap = box.gap;
  const double t = kShearBoxSlab;
  w.add_plane(Vec3::Zero(), Vec3::UnitZ(), material, "floor");
  const double lower_top = 0.5 * H - 0.5 * gap, upper_bottom = 0.5 * H + 0.5 * gap;
  const double top = fill_top + t;
  for (int half = 0; half < 2; ++half) {
    const double z0 = half == 0 ? -t : upper_bottom, z1 = half == 0 ? lower_top : top;
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

}  // namespace grainlab
