// Specimen preparation: the World, the placement and the deposit, compact
// and consolidate phases (see preparation.h).
#include "lab/preparation.h"

#include "core/error.h"
#include "geometry/shape_metrics.h"
#include "lab/deposition_friction.h"
#include "lab/packing_density.h"
#include "lab/scanned_specimen.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace grainlab {

namespace {

// For a phase that does not come to rest: the grain that holds the most
// kinetic energy, its share, speed, spin and touching contacts (a rattler
// spinning in its cage has few or none: a point contact cannot stop a spin
// about its own normal).
std::string most_energetic_grain(const World& w) {
  const std::size_t n = w.state.bodies.size();
  if (n == 0) return "no grains";
  std::size_t worst = 0;
  double worst_ke = -1, total = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double ke = kinetic_energy_of(w.model.bodies[i], w.state.bodies[i]);
    total += ke;
    if (ke > worst_ke) worst_ke = ke, worst = i;
  }
  int contacts = 0;
  const Index g = static_cast<Index>(worst);
  for (const Contact& c : w.state.contacts) contacts += in_contact(c) && (c.a == g || c.b == g);
  for (const Contact& c : w.state.wall_contacts) contacts += in_contact(c) && c.b == g;
  const BodyState& b = w.state.bodies[worst];
  return fmt::format("grain {} holds {:.0f} % of it ({:.3g} m/s, {:.3g} rad/s, {} contacts)", worst,
                     total > 0 ? 100 * worst_ke / total : 0.0, b.v.norm(), b.w.norm(), contacts);
}

// A grain's smallest extent along its principal axes (m): how thin a slot it
// can pass edge-on.
double thinnest_extent(const World& w, Index g) {
  const BodyModel& b = w.model.bodies[g];
  const Shape& s = w.model.shapes[b.shape];
  if (s.mesh.vertices.empty()) return 2 * s.bounding_radius * b.scale;  // a sphere
  return principal_frame(s.mesh).extents[2] * b.scale;
}

}  // namespace

const char* preparation_phase_name(PreparationPhase p) {
  switch (p) {
    case PreparationPhase::Deposit: return "deposit";
    case PreparationPhase::Compact: return "compact";
    case PreparationPhase::Consolidate: return "consolidate";
    case PreparationPhase::Prepared: return "prepared";
  }
  return "?";
}

SpecimenPreparation::SpecimenPreparation(const LabSpec& spec) : spec_(spec) {
  // (A scan's density is the scan's: it targets none.)
  if (spec.targets_own_indices() && !spec.own_indices_known() && spec.grains.scan.empty())
    input_error("specimen.relative_density = {} is a Dr on the grains' own index void ratios "
                "(specimen.indices = \"own\"), which are not known: measure them with `grainlab grains "
                "index` and set specimen.own_e_min and specimen.own_e_max (`grainlab run` measures them "
                "itself when they are missing), or set specimen.indices = \"lab\" to use the lab's "
                "specimen.e_min/e_max, or give specimen.void_ratio",
                spec.specimen.relative_density);
  // Left to the search (-1) and built without it: the friction the search would try first.
  spec_.specimen.deposition_friction = deposition_friction_of(spec);
  world_.settings.threads = spec.numerics.threads;  // the World's own count, set once here
  Model& m = world_.model;
  m.law = spec.material.law;
  m.gravity = Vec3(0, 0, -kStandardGravity);
  grain_material_ = m.add_material(spec.material.grain);
  Material wall = spec.material.grain;
  wall.name = "wall";
  wall.friction = spec.material.wall_friction;  // mixes by the minimum: lubricated walls stay lubricated
  const Index wall_material = m.add_material(wall);
  specimen_ = spec.grains.scan.empty() ? place_loose_specimen(world_, spec, grain_material_)
                                       : place_scanned_specimen(world_, spec, grain_material_);

  // Density scaling (automatic: S = 100). At a fixed inertial number it does
  // not change the number of loading steps (dt and the loading speed both
  // grow with sqrt(S)); it shortens deposition and consolidation, which last
  // a fixed simulated time.
  m.density_scale = spec.numerics.density_scaling > 0 ? spec.numerics.density_scaling : 100.0;
  m.rescale_bodies();
  build_shear_box(world_, spec.box, specimen_.fill_top, wall_material);

  const double critical = world_.critical_time_step();
  dt_ = spec.numerics.time_step > 0 ? spec.numerics.time_step : spec.numerics.time_step_fraction * critical;
  if (dt_ > critical)
    input_error("numerics.time_step = {:.3g} s is above the critical step {:.3g} s of these grains: "
                "use at most {:.3g} s, or raise numerics.density_scaling (the critical step grows "
                "with its square root)",
                dt_, critical, critical);
  servo_ = StressServo(Cap, box_area(), spec.consolidation.normal_stress, servo_speed_limit());
  world_.add_controller([this](World& w, double dt) {
    const bool preparing = p_.phase == PreparationPhase::Compact || p_.phase == PreparationPhase::Consolidate;
    if (preparing || (p_.phase == PreparationPhase::Prepared && hold_cap_)) servo_.control(w, dt);
  });
  if (specimen_.scan.grains > 0) {
    // A scanned specimen is consolidated where it was scanned (scanned_specimen.h).
    lower_cap_onto_grains(world_, Cap, mean_diameter());
    enter(PreparationPhase::Consolidate);
  } else {
    enter(PreparationPhase::Deposit);
  }
}

void SpecimenPreparation::apply_phase_overrides() {
  if (p_.phase == PreparationPhase::Deposit)
    world_.set_overrides(deposition_overrides(world_, spec_, grain_material_));
  else if (p_.phase == PreparationPhase::Compact)
    world_.set_overrides(compaction_overrides(spec_, grain_material_));
  else
    world_.set_overrides({});
}

void SpecimenPreparation::enter(PreparationPhase p) {
  p_.phase = p;
  p_.rest.restart();
  p_.phase_start_step[static_cast<int>(p)] = world_.state.step;
  apply_phase_overrides();
  if (p == PreparationPhase::Compact) lower_cap_onto_grains(world_, Cap, mean_diameter());
  if (p == PreparationPhase::Prepared) p_.consolidated_height = world_.state.walls[Cap].x.z();
}

bool SpecimenPreparation::check_rest(PreparationPhase p) {
  bool calm = false;
  if (p == PreparationPhase::Deposit) {
    calm = deposit_settled(world_, specimen_);
  } else {
    const auto& c = spec_.consolidation;
    const double tolerance = p == PreparationPhase::Consolidate ? c.tolerance : std::max(c.tolerance, 0.05);
    calm = std::abs(normal_stress() / c.normal_stress - 1) <= tolerance && kinetic_small_against_elastic(world_);
  }
  // The consolidation also needs the static balance (RestRun, rest_criteria.h).
  const bool rest =
      p_.rest.check(calm, world_, spec_.consolidation.max_unbalanced, p == PreparationPhase::Consolidate);
  const std::int64_t in_phase = world_.state.step - phase_step(p);
  if (!rest && in_phase > 400000)
    throw RunError(fmt::format(
        "the {} phase did not come to rest in {} steps (normal stress {:.4g} Pa, unbalanced force "
        "ratio {:.3g} averaged over {} steps, kinetic energy {:.3g} J; {}): try a smaller time step, "
        "more damping (lower restitution) or a larger consolidation.max_unbalanced",
        preparation_phase_name(p), in_phase, normal_stress(), p_.rest.last_ratio(), p_.rest.last_steps(),
        world_.kinetic_energy(), most_energetic_grain(world_)));
  return rest;
}

void SpecimenPreparation::check_grains_inside(const std::string& phase, bool shearing) const {
  const Index g = grain_outside_shear_box(world_);
  if (g < 0) return;
  const Vec3 x = world_.state.bodies[g].x * 1e3;
  const double thin = thinnest_extent(world_, g);
  throw RunError(fmt::format(
      "grain {} left the shear box in the {} phase (step {}): its centre is at ({:.2f}, {:.2f}, {:.2f}) mm, "
      "beyond the box's walls (inner box {:.2f} x {:.2f} mm, floor at z = 0). It is {:.3f} mm thick at its "
      "thinnest{}. {}",
      g, phase, world_.state.step, x.x(), x.y(), x.z(), spec_.box.length * 1e3, spec_.box.width * 1e3,
      thin * 1e3,
      shearing ? fmt::format(", against box.gap = {:.3f} mm between the halves", spec_.box.gap * 1e3) : "",
      shearing && thin <= spec_.box.gap
          ? "Grains thinner than the gap are squeezed out through it: set box.gap below the thinnest grain."
          : "A grain passes through a wall when it moves further in one step than its overlap allows: lower "
            "numerics.time_step_fraction (or set a smaller numerics.time_step)."));
}

void SpecimenPreparation::check_preparation(double e_whole, double e_bulk, const char* when) const {
  if (accept_any_density_ || specimen_.scan.grains > 0) return;  // a scan's density is the scan's
  const auto& s = spec_.specimen;
  const bool own = spec_.targets_own_indices();
  const double e = own ? e_bulk : e_whole, target = spec_.target_void_ratio();
  const double dr = own ? (s.own_e_max - e) / (s.own_e_max - s.own_e_min) : (s.e_max - e) / (s.e_max - s.e_min);
  if (own ? std::abs(dr - s.relative_density) <= s.relative_density_tolerance : std::abs(e - target) <= s.tolerance)
    return;
  throw RunError(fmt::format(
      "specimen preparation reached {}void ratio e = {:.3f} (Dr = {:.0f} % on the {} indices) {} under {:.0f} kPa, "
      "but the target is {} (Dr = {:.0f} %). {}",
      own ? "bulk " : "", e, 100 * dr, own ? "grains' own" : "lab's", when, spec_.consolidation.normal_stress * 1e-3,
      own ? fmt::format("Dr within +-{:.2f}", s.relative_density_tolerance)
          : fmt::format("e = {:.3f} +- {:.3f}", target, s.tolerance),
      100 * s.relative_density,
      e > target ? (s.deposition_friction > 0
                        ? "Lower specimen.deposition_friction for a denser specimen (or set it to -1 to "
                          "have it chosen by bisection), or set a reachable target."
                        : "Deposition is already frictionless, the densest this procedure makes: these "
                          "grains in this box do not pack that densely. Lower specimen.relative_density "
                          "or set specimen.void_ratio to a reachable value.")
      : s.deposition_friction > spec_.material.grain.friction
          ? "The specimen was deposited with more friction than the test's and collapsed when the test "
            "friction came back: a looser specimen than this needs grains with more friction."
          : "Raise specimen.deposition_friction for a looser specimen (or set it to -1 to have it chosen by "
            "bisection)."));
}

bool SpecimenPreparation::advance(int max_steps) {
  for (int i = 0; i < max_steps && !prepared(); ++i) {
    world_.step(dt_);
    const PreparationPhase p = p_.phase;
    if (world_.state.step % kCheckEvery == 0) check_grains_inside(phase_name(), false);
    p_.rest.add(world_.body_forces());
    if (world_.state.step % kCheckEvery != 0 || !check_rest(p)) continue;
    if (p == PreparationPhase::Compact) {
      p_.compacted_void_ratio = void_ratio();
      p_.compacted_bulk_void_ratio = bulk_void_ratio();
      check_preparation(p_.compacted_void_ratio, p_.compacted_bulk_void_ratio, "after compaction");
    }
    // What the test loads: a specimen deposited with more friction than the
    // test's compacts further once the test friction is back.
    if (p == PreparationPhase::Consolidate) check_preparation(void_ratio(), bulk_void_ratio(), "after consolidation");
    enter(static_cast<PreparationPhase>(static_cast<int>(p) + 1));
    return !prepared();  // a phase ended
  }
  return !prepared();
}

}  // namespace grainlab
