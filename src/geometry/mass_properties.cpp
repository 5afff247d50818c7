// Exact volume, centroid and inertia tensor of a closed, outward triangle mesh.
//
// Derivation. Pick an origin o (the vertex mean, for precision: the terms
// below are then of the size of the grain, not of its distance from the
// world origin). Every outward face (a, b, c), taken relative to o, spans
// the signed tetrahedron (0, a, b, c) with d = a . (b x c) = 6 V_tet. By the
// divergence theorem the signed tetrahedra of a closed surface add up to the
// solid exactly (parts outside the solid cancel in pairs), so
//   V        = sum d / 6
//   int x dV = sum d / 24 (a + b + c)                       (tet centroid = (a+b+c)/4)
//   C = int x x^T dV = sum d / 120 [a a^T + b b^T + c c^T + s s^T],  s = a + b + c
// The last line is the second moment of a tetrahedron with one vertex at 0:
// with x = A u over the unit tetrahedron u >= 0, sum u <= 1, A = [a b c],
// int u u^T du = (I + 1 1^T) / 120, so int x x^T dV = d A (I + 1 1^T) A^T / 120.
// About the centroid g (relative to o): C_g = C - V g g^T (parallel axes).
// Inertia per unit density: I = tr(C_g) 1 - C_g, since I_xx = int (y^2 + z^2)
// and I_xy = -int x y.
#include "geometry/mass_properties.h"

#include "core/error.h"

#include <Eigen/Eigenvalues>

namespace grainlab {

MassProperties mass_properties(const TriMesh& mesh) {
  if (mesh.vertices.empty() || mesh.faces.empty()) {
    input_error("mass properties: the mesh is empty; load it through load_mesh() first");
  }
  // Origin at the vertex mean keeps the sums well scaled.
  Vec3 origin = Vec3::Zero();
  for (const Vec3& v : mesh.vertices) origin += v;
  origin /= static_cast<double>(mesh.vertices.size());

  double six_volume = 0;
  Vec3 first = Vec3::Zero();   // 24 * int x dV
  Mat3 second = Mat3::Zero();  // 120 * int x x^T dV
  for (const Face& f : mesh.faces) {
    const Vec3 a = mesh.vertices[f[0]] - origin;
    const Vec3 b = mesh.vertices[f[1]] - origin;
    const Vec3 c = mesh.vertices[f[2]] - origin;
    const double d = a.dot(b.cross(c));
    const Vec3 s = a + b + c;
    six_volume += d;
    first += d * s;
    second += d * (a * a.transpose() + b * b.transpose() + c * c.transpose() + s * s.transpose());
  }
  const double volume = six_volume / 6.0;
  if (!(volume > 0)) {
    if (volume < 0) {
      input_error(
          "mass properties: the mesh is inside out (signed volume {:.6g} < 0: faces wind "
          "clockwise seen from outside); repair it with repair_mesh() or load it with load_mesh()",
          volume);
    }
    input_error("mass properties: the mesh has zero (or undefined) volume; it is flat, open or "
                "non-finite; check it with check_mesh()");
  }

  MassProperties mp;
  mp.volume = volume;
  const Vec3 g = first / 24.0 / volume;  // centroid relative to origin
  mp.centroid = origin + g;
  const Mat3 cov = second / 120.0 - volume * g * g.transpose();
  Mat3 inertia = cov.trace() * Mat3::Identity() - cov;
  inertia = 0.5 * (inertia + inertia.transpose());  // exact symmetry
  mp.inertia = inertia;

  // Principal frame: eigenvalues ascending, eigenvectors as columns, det = +1.
  Eigen::SelfAdjointEigenSolver<Mat3> eig(inertia);
  mp.principal_moments = eig.eigenvalues();
  Mat3 axes = eig.eigenvectors();
  if (axes.determinant() < 0) axes.col(2) = -axes.col(2);
  mp.principal_axes = axes;
  return mp;
}

}  // namespace grainlab
