// What the specimen preparation measures and reports (definitions in
// preparation.h): void ratios, Dr, coordination, the progress lines, the
// run.json values, and the preparation's own bytes.
#include "lab/preparation.h"

#include "lab/packing_density.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace grainlab {

double SpecimenPreparation::void_ratio() const {
  const double v = box_area() * world_.state.walls[Cap].x.z();
  return (v - solid_volume()) / solid_volume();
}

double SpecimenPreparation::bulk_void_ratio() const {
  const Region r = bulk_region(spec_.box.length, spec_.box.width, world_.state.walls[Cap].x.z(), mean_diameter());
  return void_ratio_in_region(world_.model, world_.state, r.lo, r.hi);
}

double SpecimenPreparation::coordination_number() const {
  const std::size_t contacts = touching_pair_count(world_.state.contacts);
  return 2.0 * contacts / std::max<std::size_t>(1, world_.model.bodies.size());
}

double SpecimenPreparation::achieved_void_ratio() const {
  if (!prepared()) return p_.compacted_void_ratio;
  return (box_area() * p_.consolidated_height - solid_volume()) / solid_volume();
}

double SpecimenPreparation::achieved_own_relative_density() const {
  const auto& s = spec_.specimen;
  if (!spec_.own_indices_known()) return std::numeric_limits<double>::quiet_NaN();
  return (s.own_e_max - p_.compacted_bulk_void_ratio) / (s.own_e_max - s.own_e_min);
}

double SpecimenPreparation::achieved_lab_relative_density() const {
  const auto& s = spec_.specimen;
  return (s.e_max - achieved_void_ratio()) / (s.e_max - s.e_min);
}

double SpecimenPreparation::achieved_relative_density() const {
  // A scan's specimen targets no density and may not know its own indices: Dr on the lab's then.
  const bool own = spec_.targets_own_indices() && spec_.own_indices_known();
  return own ? achieved_own_relative_density() : achieved_lab_relative_density();
}

std::string SpecimenPreparation::status_line() const {
  return fmt::format("sigma {:.1f} kPa  e {:.3f}", normal_stress() * 1e-3, void_ratio());
}

std::string SpecimenPreparation::phase_note() const {
  if (p_.phase != PreparationPhase::Consolidate) return "";
  if (spec_.targets_own_indices() && spec_.own_indices_known())
    return fmt::format("prepared: bulk void ratio {:.3f} (target {:.3f}), Dr {:.0f} % on the grains' own indices "
                       "(whole specimen e {:.3f})",
                       achieved_bulk_void_ratio(), spec_.target_void_ratio(), 100 * achieved_relative_density(),
                       achieved_void_ratio());
  return fmt::format("prepared: void ratio {:.3f} (target {:.3f}), Dr {:.0f} %", achieved_void_ratio(),
                     spec_.target_void_ratio(), 100 * achieved_relative_density());
}

std::vector<SummaryValue> SpecimenPreparation::summary() const {
  std::vector<SummaryValue> v = {{"", "mean_equivalent_diameter_m", mean_diameter()},
                                 {"preparation", "void_ratio", achieved_void_ratio()},
                                 {"preparation", "compacted_void_ratio", p_.compacted_void_ratio},
                                 {"preparation", "relative_density", achieved_relative_density()},
                                 {"preparation", "bulk_void_ratio", achieved_bulk_void_ratio()},
                                 {"preparation", "relative_density_lab", achieved_lab_relative_density()},
                                 {"preparation", "deposition_friction", spec_.specimen.deposition_friction},
                                 {"preparation", "target_void_ratio", spec_.target_void_ratio()}};
  if (spec_.own_indices_known()) {
    v.push_back({"preparation", "relative_density_own", achieved_own_relative_density()});
    v.push_back({"preparation", "own_e_min", spec_.specimen.own_e_min});
    v.push_back({"preparation", "own_e_max", spec_.specimen.own_e_max});
  }
  return v;
}

std::vector<SummaryValue> SpecimenPreparation::shape_summary() const {
  const GrainRepresentation& r = specimen_.representation;
  std::vector<SummaryValue> v = {{"grain_shapes", "concave_shapes", static_cast<double>(r.concave_shapes)}};
  if (r.concave_shapes > 0) {
    v.push_back({"grain_shapes", "pieces_per_concave_shape", static_cast<double>(r.pieces) / r.concave_shapes});
    v.push_back({"grain_shapes", "hull_excess_volume_fraction", r.hull_excess});
    v.push_back({"grain_shapes", "pieces_excess_volume_fraction", r.pieces_excess});
  }
  if (specimen_.scan.grains > 0) {
    v.push_back({"scan", "grains", static_cast<double>(specimen_.scan.grains)});
    v.push_back({"scan", "border_grains_dropped", static_cast<double>(specimen_.scan.border_dropped)});
    v.push_back({"scan", "position_spread", specimen_.scan.spread});
    v.push_back({"scan", "void_ratio", specimen_.scan.void_ratio});
  }
  return v;
}

void SpecimenPreparation::save(ByteWriter& b) const {
  b.i32(static_cast<std::int32_t>(p_.phase));
  p_.rest.save(b);
  servo_.save(b);
  b.f64(p_.compacted_void_ratio), b.f64(p_.compacted_bulk_void_ratio), b.f64(p_.consolidated_height);
  for (auto s : p_.phase_start_step) b.i64(s);
}

void SpecimenPreparation::load(ByteReader& r) {
  const std::int32_t phase = r.i32();
  if (phase < 0 || phase > static_cast<int>(PreparationPhase::Prepared)) r.corrupted("an unknown phase");
  p_.phase = static_cast<PreparationPhase>(phase);
  p_.rest.load(r);
  servo_.load(r);
  p_.compacted_void_ratio = r.f64(), p_.compacted_bulk_void_ratio = r.f64(), p_.consolidated_height = r.f64();
  for (auto& s : p_.phase_start_step) s = r.i64();
  apply_phase_overrides();  // the phase's settings are derived, not stored
}

std::vector<std::uint8_t> SpecimenPreparation::save() const {
  ByteWriter b;
  save(b);
  return std::move(b.bytes);
}

void SpecimenPreparation::load(std::span<const std::uint8_t> bytes) {
  ByteReader r(bytes, "the specimen preparation's state", " Start the run again without --resume.");
  load(r);
  r.expect_end();
}

}  // namespace grainlab
