// The registered contact laws. Adding a law: write its file in this folder
// (see dynamics/contact_law.h for what it provides), include it here and add
// it to RegisteredLaws: one line. Its position is its ContactLaw::index().
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

// Calls f.template operator()<Law>() for the law `law` is a handle to: a
// loop written inside f is compiled once per registered law with the law's
// functions inlined (no call through a pointer per contact; the floating
// point is that of the inlined expression, FMA contraction included).
// This one searches the given list of laws.
template <typename F, typename... Laws>
decltype(auto) with_law_in(ContactLaw law, F& f, LawList<Laws...>) {
  using Result = decltype(f.template operator()<DefaultLaw>());
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
