// Rest criteria (definitions in rest_criteria.h).
#include "lab/rest_criteria.h"

#include "dynamics/laws/registry.h"

#include <algorithm>
#include <vector>

namespace grainlab {

double contact_elastic_energy(const Model& m, const State& s) {
  // The law's energy inlined (with_law), as the contact loop of the step does.
  return with_law(m.law, [&]<typename Law>() {
    double elastic = 0;
    for (const auto* list : {&s.contacts, &s.wall_contacts})
      for (const Contact& c : *list)
        if (in_contact(c)) elastic += Law::elastic_energy(c.normal_force, c.geo.depth);
    return elastic;
  });
}

double packing_kinetic_energy(const World& w) {
  const std::size_t n = w.state.bodies.size();
  // Per sphere: its frictional contacts so far (0, 1 = all along one line, 2
  // = not), and the first one's normal.
  std::vector<char> braked(n, 0);
  std::vector<Vec3> axis(n, Vec3::Zero());
  const auto brake = [&](Index i, const Vec3& normal) {
    if (braked[i] == 0) {
      braked[i] = 1, axis[i] = normal;
    } else if (braked[i] == 1 && normal.cross(axis[i]).squaredNorm() > 1e-12) {
      braked[i] = 2;  // two lines: every spin slides one of them
    }
  };
  for (const Contact& c : w.state.contacts)
    if (in_contact(c) && w.pair(w.model.bodies[c.a].material, w.model.bodies[c.b].material).friction > 0)
      brake(c.a, c.geo.normal), brake(c.b, c.geo.normal);
  for (const Contact& c : w.state.wall_contacts)
    if (in_contact(c) && w.pair(w.model.walls[c.a].material, w.model.bodies[c.b].material).friction > 0)
      brake(c.b, c.geo.normal);
  double e = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const BodyModel& m = w.model.bodies[i];
    const BodyState& s = w.state.bodies[i];
    if (!w.model.shapes[m.shape].isotropic || braked[i] == 2) {
      e += kinetic_energy_of(m, s);
      continue;
    }
    e += 0.5 * m.mass * s.v.squaredNorm();
    if (braked[i] == 1) {  // the spin about the line of its frictional contacts is free; the rest is not
      const Vec3 slides = s.w - s.w.dot(axis[i]) * axis[i];
      e += 0.5 * m.inertia.x() * slides.squaredNorm();
    }
  }
  return e;
}

bool kinetic_small_against_elastic(const World& w) {
  return packing_kinetic_energy(w) < 1e-2 * contact_elastic_energy(w.model, w.state);
}

double per_mean_contact_force(const State& s, double force) {
  double contact = 0;
  std::size_t n_contacts = 0;
  for (const auto* list : {&s.contacts, &s.wall_contacts})
    for (const Contact& c : *list)
      if (in_contact(c)) contact += c.force.norm(), ++n_contacts;
  if (n_contacts == 0 || contact <= 0) return 1;
  return force / (contact / n_contacts);
}

double unbalanced_force_ratio(const World& w) {
  double resultant = 0;
  for (const Vec3& f : w.body_forces()) resultant += f.norm();
  return per_mean_contact_force(w.state, resultant / std::max<std::size_t>(1, w.body_forces().size()));
}

void ForceWindow::add(const std::vector<Vec3>& forces) {
  sum_.resize(forces.size(), Vec3::Zero());
  for (std::size_t k = 0; k < forces.size(); ++k) sum_[k] += forces[k];
  ++steps_;
}

void ForceWindow::reset() {
  std::fill(sum_.begin(), sum_.end(), Vec3::Zero());
  steps_ = 0;
}

double ForceWindow::averaged_ratio(const World& w) const {
  if (steps_ == 0 || sum_.empty()) return unbalanced_force_ratio(w);
  double resultant = 0;
  for (const Vec3& f : sum_) resultant += f.norm() / steps_;
  return per_mean_contact_force(w.state, resultant / sum_.size());
}

void ForceWindow::save(ByteWriter& out) const {
  out.i32(steps_);
  out.vecs(sum_);
}

void ForceWindow::load(ByteReader& in) {
  steps_ = in.i32();
  sum_ = in.vecs();
}

}  // namespace grainlab
