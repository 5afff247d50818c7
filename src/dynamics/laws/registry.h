// The registered contact laws. Adding a law: write its file in this folder
// (see dynamics/contact_law.h for what it provides, its own parameters
// included), include it here and add it to RegisteredLaws: one line. Its
// position is its ContactLaw::index(). The force loop is compiled for each
// law of RegisteredLaws; register_contact_law() adds a law at run time (a
// test's) whose parameters, validation, mixing and config keys work like any
// other's, but which the World cannot step (with_law() refuses it).
#pragma once

#include "dynamics/contact_law.h"
#include "dynamics/laws/hertz_material.h"
#include "dynamics/laws/hertz_user.h"
#include "dynamics/laws/hooke.h"

#include <cstddef>
#include <type_traits>

namespace grainlab {

// A list of law types.
template <typename... Laws>
struct LawList {
  static constexpr std::size_t size = sizeof...(Laws);
};

// Every law the engine knows, one per line.
using RegisteredLaws = LawList<
    HertzMaterialLaw,  // "hertz-material" (the default)
    HertzUserLaw,      // "hertz"
    HookeLaw>;         // "hooke"

// The law a default-constructed ContactLaw (and so a default Model) uses.
using DefaultLaw = HertzMaterialLaw;

// Position of Law in RegisteredLaws (a compile error if it is not registered).
template <typename Law, typename... Laws>
constexpr std::size_t law_index(LawList<Laws...>) {
  constexpr bool found[] = {std::is_same_v<Law, Laws>...};
  std::size_t i = 0;
  while (i < sizeof...(Laws) && !found[i]) ++i;
  return i;
}

// The table entry of a law type: its static functions behind pointers.
template <typename Law>
constexpr ContactLawEntry law_entry() {
  static_assert(Law::pair_slots <= kPairSlots, "a law's pair coefficients must fit PairCoefficients::c");
  return {Law::name,       Law::description,          Law::parameters,   Law::pair_slots,
          &Law::mix,       &Law::template at<double>, &Law::stiffness,   &Law::tangent_stiffness,
          &Law::elastic_energy};
}

// Adds a law after RegisteredLaws (call it before any other thread uses the
// registry); its handle. InputError if the name is taken.
ContactLaw register_contact_law(const ContactLawEntry& entry);

// InputError: `law` was registered at run time and has no compiled force loop.
[[noreturn]] void no_compiled_law(ContactLaw law);

// Calls f.template operator()<Law>() for the law `law` is a handle to: a
// loop written inside f is compiled once per registered law with the law's
// functions inlined (no call through a pointer per contact; the floating
// point is that of the inlined expression, FMA contraction included).
// This one searches the given list of laws.
template <typename F, typename... Laws>
decltype(auto) with_law_in(ContactLaw law, F& f, LawList<Laws...>) {
  using Result = decltype(f.template operator()<DefaultLaw>());
  if (law.index() >= sizeof...(Laws)) no_compiled_law(law);
  if constexpr (std::is_void_v<Result>) {
    std::size_t i = 0;
    ((law.index() == i++ ? (f.template operator()<Laws>(), true) : false) || ...);
  } else {
    Result out{};
    std::size_t i = 0;
    ((law.index() == i++ ? (out = f.template operator()<Laws>(), true) : false) || ...);
    return out;
  }
}

// The same over RegisteredLaws: with_law(law, [&]<typename Law>() { ... }).
template <typename F>
decltype(auto) with_law(ContactLaw law, F&& f) {
  return with_law_in(law, f, RegisteredLaws{});
}

// The handle of a registered law type, e.g. contact_law<HookeLaw>().
template <typename Law>
ContactLaw contact_law() {
  constexpr std::size_t i = law_index<Law>(RegisteredLaws{});
  static_assert(i < RegisteredLaws::size, "this contact law is not in RegisteredLaws");
  return ContactLaw::at_index(i);
}

}  // namespace grainlab
