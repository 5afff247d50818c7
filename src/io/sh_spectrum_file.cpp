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

  // The array `n` (named `name`) of `size` numbers, each >= 0 when `positive`;
  // `why` says what sets the size (e.g. "[set] degree = 3").
  std::vector<double> numbers(const toml::node& n, const std::string& name, std::size_t size, const std::string& why,
                              bool positive) const {
    const toml::array* a = n.as_array();
    if (!a) input_error("{}: {} must be an array of numbers: {} needs {}", at(n), name, why, size);
    if (a->size() != size) input_error("{}: {} has {} values but {} needs {}", at(n), name, a->size(), why, size);
    std::vector<double> out;
    for (std::size_t i = 0; i < a->size(); ++i) {
      const std::string item = fmt::format("{}[{}]", name, i);
      const double v = number((*a)[i], item);
      if (positive && v < 0) input_error("{}: {} = {} is negative; it must be >= 0", at((*a)[i]), item, v);
      out.push_back(v);
    }
    return out;
  }

  // The array [spectrum].key of degree + 1 numbers >= 0.
  std::vector<double> amplitudes(const char* key, int degree) const {
    return numbers(need("spectrum", key), fmt::format("[spectrum] {}", key), static_cast<std::size_t>(degree + 1),
                   fmt::format("[set] degree = {}", degree), true);
  }

  // [model], or an empty model when the file has none.
  ShShapeModel model(int spectrum_degree) const {
    ShShapeModel m;
    if (!root.contains("model")) return m;
    const toml::node& degree_node = need("model", "degree");
    const std::optional<std::int64_t> degree = degree_node.value_exact<std::int64_t>();
    if (!degree || *degree < 0 || *degree > spectrum_degree) {
      input_error("{}: [model] degree must be an integer in 0..{} (the [set] degree)", at(degree_node),
                  spectrum_degree);
    }
    m.degree = static_cast<int>(*degree);
    const std::size_t d = static_cast<std::size_t>(sh_count(m.degree));
    const std::string why = fmt::format("[model] degree = {}", m.degree);
    m.mean = numbers(need("model", "mean"), "[model] mean", d, why + " ((degree + 1)^2 coefficients)", false);
    m.residual = numbers(need("model", "residual"), "[model] residual", static_cast<std::size_t>(m.degree + 1),
                         why + " (one per degree)", true);
    const toml::node& sigma = need("model", "sigma");
    const toml::array* sa = sigma.as_array();
    if (!sa) input_error("{}: [model] sigma must be an array of numbers, one per component", at(sigma));
    m.sigma = numbers(sigma, "[model] sigma", sa->size(), "one per component", true);
    const toml::node& comps = need("model", "components");
    const toml::array* ca = comps.as_array();
    if (!ca || ca->size() != m.sigma.size()) {
      input_error("{}: [model] components must be an array of {} arrays (one per sigma value)", at(comps),
                  m.sigma.size());
    }
    for (std::size_t i = 0; i < ca->size(); ++i) {
      m.components.push_back(
          numbers((*ca)[i], fmt::format("[model] components[{}]", i), d, why + " ((degree + 1)^2 coefficients)", false));
    }
    try {
      validate(m);
    } catch (const InputError& e) {
      input_error("{}: [model]: {}", at(degree_node), e.what());
    }
    return m;
  }
};

// Seven significant digits: a component's length stays 1 within 1e-6.
std::string numbers_toml(const std::vector<double>& v) {
  std::string s = "[";
  for (std::size_t i = 0; i < v.size(); ++i) s += fmt::format("{}{:.7g}", i ? ", " : "", v[i]);
  return s + "]";
}

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
  s.model = r.model(static_cast<int>(*degree));
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

std::string sh_model_toml(const ShShapeModel& m) {
  if (m.empty()) return "";
  std::string text = fmt::format(
      "\n[model]\n"
      "# Shape model: grains in their principal frames, coefficients of degree <= {} divided by a_00, as real\n"
      "# vectors x (x_n0 = a_n0, x_nm = sqrt2 Re a_nm, x_n-m = sqrt2 Im a_nm); their mean, the {} main\n"
      "# components (unit vectors) and the standard deviation of the grains' scores along each; residual:\n"
      "# RMS amplitude per degree of what those components leave.\n"
      "degree = {}\nmean = {}\nsigma = {}\nresidual = {}\ncomponents = [\n",
      m.degree, m.components.size(), m.degree, numbers_toml(m.mean), numbers_toml(m.sigma), numbers_toml(m.residual));
  for (const auto& v : m.components) text += "  " + numbers_toml(v) + ",\n";
  return text + "]\n";
}

}  // namespace grainlab
