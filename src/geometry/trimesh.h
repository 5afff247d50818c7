// A triangle mesh: the shape of a grain as scanned or generated.
#pragma once

#include "core/types.h"

#include <array>
#include <vector>

namespace grainlab {

using Face = std::array<Index, 3>;

// Closed triangle surface. Faces are counter-clockwise seen from outside, so
// (b - a) x (c - a) points outward. Units are the file's (metres in grainlab).
struct TriMesh {
  std::vector<Vec3> vertices;
  std::vector<Face> faces;
};

}  // namespace grainlab
