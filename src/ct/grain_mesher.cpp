#include "ct/grain_mesher.h"

#include "core/error.h"
#include "ct/marching_tetrahedra.h"
#include "ct/taubin_smooth.h"
#include "ct/voxelize.h"
#include "geometry/mesh_check.h"
#include "geometry/simplify.h"

#include <algorithm>
#include <cmath>

namespace grainlab::ct {

namespace {

// Voxels around the grain's box: its surface closes inside the crop, even after the denoising blur.
std::int64_t padding(const MeshingOptions& o) { return 2 + static_cast<std::int64_t>(std::ceil(3 * o.denoise)); }

}  // namespace

GrainMesh mesh_grain(const LabelVolume& labels, const Region& region, const std::optional<GreyField>& grey,
                     const MeshingOptions& options) {
  // The field on the grain's box grown by kPad voxels (outside the image: pore).
  const std::int64_t kPad = padding(options);
  Size3 lo, crop;
  for (int a = 0; a < 3; ++a) {
    lo[a] = region.lo[a] - kPad;
    crop[a] = region.hi[a] - region.lo[a] + 1 + 2 * kPad;
  }
  const float iso = grey ? grey->threshold : 0.5f;
  const float pore = grey ? grey->pore_level : 0.0f;
  // Filled pores and cleared specks move just across the threshold: 5 % of the contrast.
  const float nudge = grey ? 0.05f * (grey->solid_level - grey->pore_level) : 0.0f;
  std::vector<float> field(static_cast<std::size_t>(crop[0] * crop[1] * crop[2]), pore);
  for (std::int64_t k = 0; k < crop[2]; ++k) {
    for (std::int64_t j = 0; j < crop[1]; ++j) {
      for (std::int64_t i = 0; i < crop[0]; ++i) {
        const std::int64_t gi = lo[0] + i, gj = lo[1] + j, gk = lo[2] + k;
        if (gi < 0 || gj < 0 || gk < 0 || gi >= labels.size[0] || gj >= labels.size[1] || gk >= labels.size[2]) {
          continue;
        }
        const std::uint32_t l = labels.at(gi, gj, gk);
        float& f = field[static_cast<std::size_t>(i + crop[0] * (j + crop[1] * k))];
        if (!grey) {
          f = l == region.label ? 1.0f : 0.0f;
        } else if (l == region.label) {
          f = std::max(grey->grey->at(gi, gj, gk), iso + nudge);
        } else if (l == 0) {
          f = std::min(grey->grey->at(gi, gj, gk), iso - nudge);
        }
      }
    }
  }

  if (options.denoise > 0) {
    GreyVolume f;
    f.size = crop;
    f.values = std::move(field);
    gaussian_blur(f, options.denoise);
    field = std::move(f.values);
    // The outer layer must stay below iso for a closed surface.
    for (std::int64_t k = 0; k < crop[2]; ++k) {
      for (std::int64_t j = 0; j < crop[1]; ++j) {
        for (std::int64_t i = 0; i < crop[0]; ++i) {
          if (i == 0 || j == 0 || k == 0 || i == crop[0] - 1 || j == crop[1] - 1 || k == crop[2] - 1) {
            field[static_cast<std::size_t>(i + crop[0] * (j + crop[1] * k))] = pore;
          }
        }
      }
    }
  }

  GrainMesh out;
  std::vector<TriMesh> pieces = mesh_components(iso_surface(field, crop, iso));
  if (pieces.empty()) throw RunError(fmt::format("grain {}: the iso-surface is empty", region.label));
  out.dropped_pieces = static_cast<int>(pieces.size()) - 1;
  TriMesh mesh = std::move(pieces.front());
  taubin_smooth(mesh, options.smooth_iterations);

  // Voxel indices (crop-relative) to world coordinates; a mirroring direction matrix flips the winding back.
  for (Vec3& v : mesh.vertices) v = labels.world(v + Vec3(lo[0], lo[1], lo[2]));
  if (labels.direction.determinant() < 0) {
    for (Face& f : mesh.faces) std::swap(f[1], f[2]);
  }
  SimplifyResult s = simplify_mesh(mesh, options.faces);
  out.mesh = std::move(s.mesh);
  out.within_budget = s.within_budget;
  const MeshCheck check = check_mesh(out.mesh);
  if (!check.ok()) {
    throw RunError(fmt::format("grain {}: its mesh failed the check ({}); please report this with the image",
                               region.label, check.describe()));
  }
  return out;
}

}  // namespace grainlab::ct
