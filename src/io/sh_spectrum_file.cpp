// Spectrum files (see sh_spectrum_file.h), parsed with toml++.
#include "io/sh_spectrum_file.h"

#include "core/bounded_read.h"
#include "core/error.h"

#include <toml++/toml.h>

#include <cmath>

namespace grainlab {
namespace {

constexpr const char* kHowToMake = "write it with `grainlab grains spectrum GRAINS --out FILE`";

struct Reader {
  std::string file;
  const toml::table& root;

  std::string at(const toml::node& n) const { return fmt::format("{}:{}", file, n.source().begin.line); }

  const toml::node& need(const char* table, const char* key) const {
    const toml::node* n = root.at_path(fmt::format("{}.{}", table, key)).node();
    if (!n) input_error("{}: missing key `{}` in [{}]; {}", file, key, table, kHowToMake);
    return *n;
  }

  double number(const toml::node& n, const std::string& key) const {
    const std::optional<double> v = n.value<double>();
    if (!v) {
      input_error("{}: {} must be a number, got a {}", at(n), key,
                  toml::impl::node_type_friendly_names[static_cast<int>(n.type())]);
    }
    if (!std::isfinite(*v)) input_error("{}: {} = {} is not a finite number", at(n), key, *v);
    return *v;
  }

  // The array [spectrum].key of degree + 1 numbers >= 0.
  std::vector<double> amplitudes(const char* key, int degree) const {
    const toml::node& n = need("spectrum", key);
    const toml::array* a = n.as_array();
    if (!a) input_error("{}: [spectrum] {} must be an array of numbers, one per degree n = 0..{}", at(n), key, degree);
    if (static_cast<int>(a->size()) != degree + 1) {
      input_error("{}: [spectrum] {} has {} values but [set] degree = {} needs {} (n = 0..degree)", at(n), key,
                  a->size(), degree, degree + 1);
    }
    std::vector<double> out;
    for (std::size_t i = 0; i < a->size(); ++i) {
      const std::string name = fmt::format("[spectrum] {}[{}]", key, i);
      const double v = number((*a)[i], name);
      if (v < 0) {
        input_error("{}: {} = {} is negative; amplitudes A_n / A_0 and their spreads are >= 0", at((*a)[i]), name, v);
      }
      out.push_back(v);
    }
    return out;
  }
};

}  // namespace

ShSpectrumFile read_sh_spectrum(const std::filesystem::path& path) {
  const std::string file = path.string();
  std::error_code ec;  // a device or a folder is refused by read_bounded_file, saying what it is
  if (!std::filesystem::exists(path, ec)) input_error("spectrum file '{}' does not exist; {}", file, kHowToMake);
  toml::table root;
  try {
    root = toml::parse(read_bounded_file(path, 4 * kMiB, "spectrum file"), file);
  } catch (const toml::parse_error& e) {
    input_error("{}:{}: TOML syntax error: {}", file, e.source().begin.line, excerpt(e.description(), 300));
  }
  const Reader r{file, root};
  ShSpectrumFile out;
  const toml::node& degree_node = r.need("set", "degree");
  const std::optional<std::int64_t> degree = degree_node.value_exact<std::int64_t>();
  if (!degree || *degree < 0 || *degree > 200) {
    input_error("{}: [set] degree must be an integer in 0..200 (the highest degree n of the spectrum)",
                r.at(degree_node));
  }
  ShSpectrum& s = out.spectrum;
  s.mean = r.amplitudes("mean", static_cast<int>(*degree));
  s.std = r.amplitudes("std", static_cast<int>(*degree));
  const auto d = [&](const char* key) {
    return r.number(r.need("shape", fmt::format("equivalent_diameter_m.{}", key).c_str()),
                    fmt::format("[shape] equivalent_diameter_m.{}", key));
  };
  s.d_eq_mean = d("mean");
  s.d_eq_std = d("std");
  s.d_eq_min = d("min");
  s.d_eq_max = d("max");
  for (const char* key : kSpectrumShapeKeys) {
    if (const toml::node* n = root.at_path(fmt::format("shape.{}.mean", key)).node()) {
      out.shape_means.emplace_back(key, r.number(*n, fmt::format("[shape] {}.mean", key)));
    }
  }
  try {
    validate(s);
  } catch (const InputError& e) {
    input_error("{}: {}", file, e.what());
  }
  return out;
}

}  // namespace grainlab
