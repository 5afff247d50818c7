// Fabric tensors (definitions and derivations in fabric.h).
#include "analysis/fabric.h"

#include "analysis/preconditions.h"

#include <Eigen/Eigenvalues>

#include <cmath>
#include <stdexcept>

namespace grainlab::analysis {

std::vector<Vec3> contact_normals(const State& s, const GrainMask* mask) {
  check_mask(mask, s.bodies.size(), "contact_normals");
  std::vector<Vec3> n;
  for (const Contact& pc : s.contacts) {
    if (!in_contact(pc)) continue;
    const int copies = mask ? ((*mask)[pc.a] != 0) + ((*mask)[pc.b] != 0) : 1;
    for (int c = 0; c < copies; ++c) n.push_back(pc.geo.normal);
  }
  return n;
}

FabricTensors fabric_tensors(std::span<const Vec3> normals, std::span<const double> weights) {
  if (!weights.empty() && weights.size() != normals.size())
    throw std::invalid_argument(fmt::format("fabric_tensors: {} weights for {} normals", weights.size(), normals.size()));
  FabricTensors f;
  f.count = normals.size();
  for (std::size_t m = 0; m < normals.size(); ++m) {
    const double len = normals[m].norm();
    if (!(len > 0) || !std::isfinite(len))
      throw std::invalid_argument(fmt::format("fabric_tensors: normal {} has length {}", m, len));
    const double w = weights.empty() ? 1.0 : weights[m];
    if (!(w >= 0) || !std::isfinite(w))
      throw std::invalid_argument(fmt::format("fabric_tensors: weight {} is {}", m, w));
    const Vec3 n = normals[m] / len;
    f.phi += w * n * n.transpose();
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const double wij = w * n[i] * n[j];
        for (int k = 0; k < 3; ++k)
          for (int l = 0; l < 3; ++l) f.phi4(i, j, k, l) += wij * n[k] * n[l];
      }
    f.total_weight += w;
  }
  if (f.count > 0) {
    if (!(f.total_weight > 0)) throw std::invalid_argument("fabric_tensors: all weights are zero");
    f.phi /= f.total_weight;
    f.phi4 = (1.0 / f.total_weight) * f.phi4;
  }
  return f;
}

Mat3 deviatoric_part(const Mat3& phi) { return phi - (phi.trace() / 3.0) * Mat3::Identity(); }

Tensor4 deviatoric_part(const Tensor4& phi4) {
  const Mat3 phi2 = phi4.trace();
  return phi4 + (-6.0 / 7.0) * sym_delta_outer(phi2) + (3.0 / 35.0 * phi2.trace()) * sym_delta_delta();
}

Principal principal(const Mat3& phi) {
  const Eigen::SelfAdjointEigenSolver<Mat3> eig(0.5 * (phi + phi.transpose()));
  Principal p;
  for (int k = 0; k < 3; ++k) {  // Eigen sorts ascending
    p.values[k] = eig.eigenvalues()[2 - k];
    p.directions.col(k) = eig.eigenvectors().col(2 - k);
  }
  if (p.directions.determinant() < 0) p.directions.col(2) *= -1.0;
  return p;
}

double octahedral_fabric_factor(const Vec3& v) {
  const double a = v[0] - v[1], b = v[0] - v[2], c = v[1] - v[2];
  return std::sqrt(0.5 * (a * a + b * b + c * c));
}

double octahedral_fabric_factor(const Mat3& phi) {
  const Mat3 sym = 0.5 * (phi + phi.transpose());
  return std::sqrt(1.5) * deviatoric_part(sym).norm();
}

}  // namespace grainlab::analysis
