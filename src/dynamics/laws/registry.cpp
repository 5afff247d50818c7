// The table of registered laws' functions, built from RegisteredLaws (and
// extended by register_contact_law), and the law-independent parts of
// validation and mixing: mu = min(mu_a, mu_b), then the law's own mix; every
// parameter checked against its law's rule.
#include "dynamics/laws/registry.h"

#include "core/error.h"

#include <algorithm>
#include <vector>

namespace grainlab {

namespace {

template <typename... Laws>
std::vector<ContactLawEntry> entries_of(LawList<Laws...>) {
  return {law_entry<Laws>()...};
}

std::vector<ContactLawEntry>& laws() {
  static std::vector<ContactLawEntry> table = entries_of(RegisteredLaws{});
  return table;
}

}  // namespace

ContactLaw::ContactLaw() : index_(static_cast<std::uint8_t>(law_index<DefaultLaw>(RegisteredLaws{}))) {}

ContactLaw ContactLaw::at_index(std::size_t index) {
  if (index >= laws().size())
    input_error("contact law number {} is not registered ({} laws are)", index, laws().size());
  ContactLaw law;
  law.index_ = static_cast<std::uint8_t>(index);
  return law;
}

const ContactLawEntry& ContactLaw::operator*() const { return laws()[index_]; }

ContactLaw register_contact_law(const ContactLawEntry& entry) {
  for (const ContactLawEntry& e : laws())
    if (std::string_view(e.name) == entry.name) input_error("contact law '{}' is registered already", entry.name);
  if (entry.pair_slots > kPairSlots)
    input_error("contact law '{}' uses {} pair coefficients; at most {} fit", entry.name, entry.pair_slots, kPairSlots);
  laws().push_back(entry);
  return ContactLaw::at_index(laws().size() - 1);
}

void no_compiled_law(ContactLaw law) {
  input_error("contact law '{}' has no compiled force loop: add it to RegisteredLaws (dynamics/laws/registry.h)",
              law->name);
}

ContactLaw parse_contact_law(const std::string& name) {
  for (std::size_t i = 0; i < laws().size(); ++i)
    if (name == laws()[i].name) return ContactLaw::at_index(i);
  std::string choices;
  for (const ContactLawEntry& e : laws()) choices += fmt::format("{}{}", choices.empty() ? "" : ", ", contact_law_summary(e));
  input_error("unknown contact law '{}': use one of {}", name, choices);
}

const char* contact_law_name(ContactLaw law) { return law->name; }

std::string contact_law_names() {
  std::string out;
  for (const ContactLawEntry& e : laws()) out += fmt::format("{}\"{}\"", out.empty() ? "" : ", ", e.name);
  return out;
}

std::span<const ContactLawEntry> contact_laws() { return laws(); }

std::string contact_law_summary(const ContactLawEntry& law) {
  std::string keys;
  for (const LawParameter& p : law.parameters)
    keys += fmt::format("{}{}{}", keys.empty() ? "" : ", ", p.key, *p.unit ? fmt::format(" ({})", p.unit) : "");
  return fmt::format("\"{}\" ({}: {})", law.name, law.description, keys);
}

PairCoefficients mix(const Material& a, const Material& b, ContactLaw law) {
  PairCoefficients p = law->mix(a, b);
  p.friction = std::min(a.friction, b.friction);
  return p;
}

std::string parameter_rule(const LawParameter& p) {
  return *p.unit ? fmt::format("{} ({})", p.rule, p.unit) : std::string(p.rule);
}

namespace {

// Throws InputError "material 'name': field = value is impossible; it must be rule" unless ok.
void require(const Material& m, bool ok, const char* field, double value, std::string_view rule) {
  if (!ok) input_error("material '{}': {} = {} is impossible; it must be {}", m.name, field, value, rule);
}

}  // namespace

void validate(const Material& m, ContactLaw law) {
  require(m, m.density > 0 && std::isfinite(m.density), "density", m.density, "> 0 (kg/m^3)");
  require(m, m.friction >= 0 && std::isfinite(m.friction), "friction", m.friction, ">= 0");
  for (const LawParameter& p : law->parameters) {
    const double v = parameter_value(m, p);
    require(m, p.accepts(v), p.key, v, parameter_rule(p));
  }
}

}  // namespace grainlab
