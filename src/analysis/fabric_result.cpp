// The fabric result of a set of contacts (contents in fabric_result.h).
#include "analysis/fabric_result.h"

namespace grainlab::analysis {

FabricResult fabric_result(const State& s, const GrainMask* mask) {
  FabricResult r;
  r.normals = contact_normals(s, mask);
  r.contacts = r.normals.size();
  if (r.normals.empty()) return r;
  const FabricTensors f = fabric_tensors(r.normals);  // normalises each normal itself
  for (Vec3& n : r.normals) n.normalize();
  r.phi = f.phi;
  r.density = kanatani_density(f);
  r.principal = principal(f.phi);
  r.psi = octahedral_fabric_factor(r.principal.values);
  r.rose = rose_histogram(r.normals);
  r.kanatani_grid = sample_density(r.density);
  return r;
}

}  // namespace grainlab::analysis
