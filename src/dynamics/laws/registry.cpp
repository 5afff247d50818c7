// The table of registered laws' functions, built from RegisteredLaws, and the
// law-independent parts of validation and mixing.
#include "dynamics/laws/registry.h"

#include "core/error.h"

#include <algorithm>
#include <array>

namespace grainlab {

namespace {

template <typename Law>
constexpr ContactLawEntry entry_of() {
  return {Law::name,       Law::parameters, &Law::validate,          &Law::mix,
          &Law::template at<double>, &Law::stiffness, &Law::tangent_stiffness, &Law::elastic_energy};
}

template <typename... Laws>
constexpr std::array<ContactLawEntry, sizeof...(Laws)> entries_of(LawList<Laws...>) {
  return {entry_of<Laws>()...};
}

constexpr auto kLaws = entries_of(RegisteredLaws{});

}  // namespace

ContactLaw::ContactLaw() : index_(static_cast<std::uint8_t>(law_index<DefaultLaw>(RegisteredLaws{}))) {}

ContactLaw ContactLaw::at_index(std::size_t index) {
  if (index >= kLaws.size()) input_error("contact law number {} is not registered ({} laws are)", index, kLaws.size());
  ContactLaw law;
  law.index_ = static_cast<std::uint8_t>(index);
  return law;
}

const ContactLawEntry& ContactLaw::operator*() const { return kLaws[index_]; }

ContactLaw parse_contact_law(const std::string& name) {
  for (std::size_t i = 0; i < kLaws.size(); ++i)
    if (name == kLaws[i].name) return ContactLaw::at_index(i);
  std::string choices;
  for (const ContactLawEntry& e : kLaws) choices += fmt::format("{}\"{}\" ({})", choices.empty() ? "" : ", ", e.name, e.parameters);
  input_error("unknown contact law '{}': use one of {}", name, choices);
}

const char* contact_law_name(ContactLaw law) { return law->name; }

std::string contact_law_names() {
  std::string out;
  for (const ContactLawEntry& e : kLaws) out += fmt::format("{}\"{}\"", out.empty() ? "" : ", ", e.name);
  return out;
}

PairCoefficients mix(const Material& a, const Material& b, ContactLaw law) {
  PairCoefficients p = law->mix(a, b);
  p.friction = std::min(a.friction, b.friction);
  return p;
}

void require_material_field(const Material& m, bool ok, const char* field, double value, const char* rule) {
  if (!ok) input_error("material '{}': {} = {} is impossible; it must be {}", m.name, field, value, rule);
}

void validate(const Material& m, ContactLaw law) {
  require_material_field(m, m.density > 0 && std::isfinite(m.density), "density", m.density, "> 0 (kg/m^3)");
  require_material_field(m, m.friction >= 0 && std::isfinite(m.friction), "friction", m.friction, ">= 0");
  law->validate(m);
}

}  // namespace grainlab
