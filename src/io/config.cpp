// Config parsing with toml++ (compiled library, exceptions on): syntax errors
// come from toml::parse_error with a source position; keys and values carry
// node.source() for their line. Parsing walks the file against the key list
// of spec_fields.h, so unknown tables and keys are found with a suggestion
// (closest valid name by edit distance), values are checked for type, the
// sand preset goes first, and validate() checks every value for sense.
#include "core/text.h"
#include "io/config.h"

#include "core/bounded_read.h"
#include "core/error.h"
#include "io/spec_fields.h"
#include "lab/lab_registry.h"
#include "grains/generator.h"
#include "lab/sand_presets.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <toml++/toml.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <sstream>
#include <system_error>

namespace grainlab {

// ---------------------------------------------------------------------------
// The key list.

namespace {

#define GL_FIELD(table, key, member, doc) \
  SpecField { table, key, doc, [](LabSpec& s) -> SpecFieldRef { return &s.member; } }

// The keys before the registered tests' tables.
const std::array kHeadFields{
    GL_FIELD("", "test", test, ""),  // its doc names the registered tests (spec_fields())
    GL_FIELD("", "seed", seed, "seed of every random choice (grain shapes, sizes, placement); same seed, same run"),

    GL_FIELD("grains", "preset", grains.preset, "synthetic grain class: glass-beads | rounded | sub-angular | angular (random rounded polytopes), or a spherical-harmonic sand drawn from the shape statistics of 16 CT-scanned grains: sh-ottawa | sh-river | sh-limestone (concave, sized to the sieve range; grains.convexity does not apply)"),
    GL_FIELD("grains", "folder", grains.folder, "if not empty: import every STL/OBJ/PLY mesh and spherical-harmonic .dat file in this folder instead of the preset"),
    GL_FIELD("grains", "shapes", grains.shapes, "number of distinct grain shapes in the library (grains reuse them, scaled)"),
    GL_FIELD("grains", "faces", grains.faces, "face budget per grain shape (>= 100)"),
    GL_FIELD("grains", "d_min", grains.d_min, "m, smallest sieve size (0.707 mm: retained on sieve #25)"),
    GL_FIELD("grains", "d_max", grains.d_max, "m, largest sieve size (0.841 mm: passing sieve #20)"),
    GL_FIELD("grains", "convexity", grains.convexity,
             "generated grains: volume / convex hull volume, 0.8-1 (< 1 presses two dents into each grain)"),
    GL_FIELD("grains", "scan", grains.scan,
             "if not empty: a folder from `grainlab ct segment` (grains.csv and meshes): its grains are placed "
             "where they were scanned and consolidated, without deposition (preset and folder are ignored)"),
    GL_FIELD("grains", "scan_border", grains.scan_border,
             "scanned grains touching the image border (cut by it): drop | keep"),
    GL_FIELD("grains", "representation", grains.representation,
             "collision shape: auto (concave pieces below convexity 0.98, else the hull) | hull | concave"),

    GL_FIELD("material", "preset", material.preset, "sand preset applied first: crushed-limestone | griffin | ottawa | glass-beads | \"\" (none)"),
    GL_FIELD("material", "contact_law", material.law, "the contact law (its parameters: [material.<law>])"),
    GL_FIELD("material", "density", material.grain.density, "kg/m^3, grain density"),
    GL_FIELD("material", "friction", material.grain.friction, "Coulomb friction coefficient between grains during shear"),
    GL_FIELD("material", "wall_friction", material.wall_friction, "friction coefficient between grains and the box walls and cap"),

    GL_FIELD("box", "length", box.length, "m, along the shear direction x"),
    GL_FIELD("box", "width", box.width, "m, along y"),
    GL_FIELD("box", "height", box.height, "m, target specimen height after preparation"),
    GL_FIELD("box", "gap", box.gap,
             "m, opening between the lower and upper halves (direct shear; closed while the specimen is made, "
             "opened when the shear begins)"),

    GL_FIELD("specimen", "relative_density", specimen.relative_density, "target Dr = (e_max - e)/(e_max - e_min) on specimen.indices, in [0, 1]"),
    GL_FIELD("specimen", "indices", specimen.indices, "\"own\": Dr on the grains' own index voids (own_e_min/own_e_max; measured when 0, built in for the default grains) | \"lab\": on the lab's e_min/e_max"),
    GL_FIELD("specimen", "own_e_max", specimen.own_e_max, "the grains' own loosest void ratio (`grainlab grains index`); 0 = the run measures it"),
    GL_FIELD("specimen", "own_e_min", specimen.own_e_min, "the grains' own densest void ratio (`grainlab grains index`); 0 = the run measures it"),
    GL_FIELD("specimen", "e_max", specimen.e_max, "the lab's maximum index void ratio of the real sand (reported; the target with indices = \"lab\")"),
    GL_FIELD("specimen", "e_min", specimen.e_min, "the lab's minimum index void ratio of the real sand"),
    GL_FIELD("specimen", "void_ratio", specimen.void_ratio, "if > 0: target void ratio of the whole specimen, overrides relative_density"),
    GL_FIELD("specimen", "tolerance", specimen.tolerance, "accepted |e - e_target| (void_ratio and lab-index targets)"),
    GL_FIELD("specimen", "relative_density_tolerance", specimen.relative_density_tolerance, "accepted |Dr - Dr_target| (own-index targets)"),
    GL_FIELD("specimen", "deposition_friction", specimen.deposition_friction, "friction between grains while raining and compacting (lower: denser); -1 = chosen by the preparation search over trial preparations, the first at the grain class's measured friction (rounded: 0.032)"),
    GL_FIELD("specimen", "from", specimen.from, "path of a specimen.bin that a run wrote in its output folder as its loading began: shear that same specimen (another material, damping or loading) instead of preparing one; \"\" = prepare"),

    GL_FIELD("consolidation", "normal_stress", consolidation.normal_stress, "Pa, normal stress held by the top cap (100 kPa = 100e3)"),
    GL_FIELD("consolidation", "tolerance", consolidation.tolerance, "relative stress error accepted, in (0, 1)"),
    GL_FIELD("consolidation", "max_unbalanced", consolidation.max_unbalanced, "unbalanced-force ratio accepted as at rest"),

};

// The keys after the registered tests' tables.
const std::array kTailFields{
    GL_FIELD("numerics", "time_step", numerics.time_step, "s; 0 = time_step_fraction x the critical step"),
    GL_FIELD("numerics", "time_step_fraction", numerics.time_step_fraction, "fraction of the critical step used when time_step = 0, in (0, 1]"),
    GL_FIELD("numerics", "density_scaling", numerics.density_scaling, "factor on inertia (not weight); 0 = automatic"),
    GL_FIELD("numerics", "inertial_number", numerics.inertial_number, "target I = gamma_dot d sqrt(rho / p) when shear.speed = 0"),
    GL_FIELD("numerics", "threads", numerics.threads,
             "worker threads; 0 = automatic: up to all cores, the count whose steps run fastest, timed as the run goes"),

    GL_FIELD("output", "folder", output.folder, "where the run writes its files"),
    GL_FIELD("output", "strain_interval", output.strain_interval, "sample series.csv every this much shear strain (triaxial: axial strain)"),
    GL_FIELD("output", "checkpoint_interval", output.checkpoint_interval, "s of wall-clock time between checkpoints"),
    GL_FIELD("output", "snapshot_interval", output.snapshot_interval, "ParaView snapshot (paraview/*.vtp) every this much shear (triaxial: axial) strain; 0 = start and end of shear only"),
};

#undef GL_FIELD

// The shared tables: those before the registered tests' tables, then the rest.
constexpr std::array<SpecTable, 5> kHeadTables{{
    {"grains", "the grains: a synthetic class or a folder of scanned meshes, and the sieve range"},
    {"material", "grain material and contact law (SI units)"},
    {"box", "the box: split in two halves for the direct shear, one rigid ring (no gap) for the oedometer"},
    {"specimen", "the specimen's target density"},
    {"consolidation", "servo-controlled consolidation under the top cap"},
}};
constexpr std::array<SpecTable, 2> kTailTables{{
    {"numerics", "time step, density scaling, threads"},
    {"output", "what the run writes, and where"},
}};

// The grain classes grains/ can generate.
constexpr std::array<std::string_view, 7> kGrainClasses{"glass-beads", "rounded",   "sub-angular", "angular",
                                                        "sh-ottawa",   "sh-river", "sh-limestone"};

// The flat [material] keys of the registered laws' parameters, each key once
// (laws that declare the same key share its value), in registry order.
std::vector<SpecField> law_fields() {
  std::vector<SpecField> out;
  for (const ContactLawEntry& law : contact_laws())
    for (const LawParameter& p : law.parameters) {
      if (std::any_of(out.begin(), out.end(), [&](const SpecField& f) { return f.key == p.key; })) continue;
      const LawParameter* q = &p;
      out.push_back({"material", p.key, std::string(p.meaning),
                     [q](LabSpec& s) -> SpecFieldRef { return &parameter_value(s.material.grain, *q); }, q});
    }
  return out;
}

// The key list and the tables for the tests and laws registered now: the
// shared keys, each test's table, and the laws' parameters after
// material.friction.
struct KeyList {
  std::vector<SpecField> fields;
  std::vector<SpecTable> tables;
  std::size_t tests = 0, laws = 0;  // the registrations it was built for
};

KeyList build_key_list() {
  KeyList k;
  const std::vector<LabTestEntry>& entries = lab_test_entries();
  k.fields.assign(kHeadFields.begin(), kHeadFields.end());
  k.tables.assign(kHeadTables.begin(), kHeadTables.end());
  std::string doc = "the lab test:";
  for (const LabTestEntry& e : entries) {
    doc += fmt::format("{} \"{}\" (reads [{}])", &e == &entries.front() ? "" : " |", e.name, e.keys.table.name);
    k.fields.insert(k.fields.end(), e.keys.fields.begin(), e.keys.fields.end());
    k.tables.push_back(e.keys.table);
  }
  k.fields.front().doc = doc;  // the key `test`
  k.fields.insert(k.fields.end(), kTailFields.begin(), kTailFields.end());
  k.tables.insert(k.tables.end(), kTailTables.begin(), kTailTables.end());
  std::string law_doc = "the contact law:";
  for (const ContactLawEntry& law : contact_laws())
    law_doc += fmt::format("{} {}", &law == contact_laws().data() ? "" : " |", contact_law_summary(law));
  const auto friction = std::find_if(k.fields.begin(), k.fields.end(), [](const SpecField& f) {
    return f.table == "material" && f.key == "friction";
  });
  const std::vector<SpecField> laws = law_fields();
  k.fields.insert(friction + 1, laws.begin(), laws.end());
  for (SpecField& f : k.fields)
    if (f.table == "material" && f.key == "contact_law") f.doc = law_doc;
  k.tests = entries.size();
  k.laws = contact_laws().size();
  return k;
}

// Built once, and again only after a test or a law is registered (every list
// built is kept, so a reference to an earlier one stays valid); a call finds
// the current one without a lock.
const KeyList& key_list() {
  static std::atomic<const KeyList*> current{nullptr};
  static std::mutex mutex;
  static std::vector<std::unique_ptr<const KeyList>> built;
  const auto fresh = [](const KeyList* k) {
    return k && k->tests == lab_test_entries().size() && k->laws == contact_laws().size();
  };
  if (const KeyList* k = current.load(std::memory_order_acquire); fresh(k)) return *k;
  const std::lock_guard lock(mutex);
  if (const KeyList* k = current.load(std::memory_order_relaxed); fresh(k)) return *k;
  built.push_back(std::make_unique<const KeyList>(build_key_list()));
  current.store(built.back().get(), std::memory_order_release);
  return *built.back();
}

// The registered law named `name`, or null.
const ContactLawEntry* find_law(std::string_view name) {
  for (const ContactLawEntry& law : contact_laws())
    if (law.name == name) return &law;
  return nullptr;
}

}  // namespace

const std::vector<SpecField>& spec_fields() { return key_list().fields; }
const std::vector<SpecTable>& spec_tables() { return key_list().tables; }

// ---------------------------------------------------------------------------
// Helpers shared by parsing and validation.

namespace {

// Dotted key -> line in the file (absent: not given in the file).
using LineMap = std::map<std::string, int, std::less<>>;

std::string where(const std::string& source, int line, int column = 0) {
  if (line <= 0) return source;
  if (column <= 0) return fmt::format("{} (line {})", source, line);
  return fmt::format("{} (line {}, column {})", source, line, column);
}

int line_of(const toml::source_region& r) { return static_cast<int>(r.begin.line); }

// " Did you mean 'x'?" when a candidate is close enough, else "".
std::string suggestion(std::string_view name, const std::vector<std::string>& candidates) {
  std::string best;
  std::size_t best_d = std::numeric_limits<std::size_t>::max();
  for (const std::string& c : candidates) {
    const std::size_t d = edit_distance(name, c);
    if (d < best_d) best_d = d, best = c;
  }
  const std::size_t limit = std::max<std::size_t>(2, name.size() / 3);
  return best_d <= limit ? fmt::format(" Did you mean '{}'?", best) : std::string();
}

std::vector<std::string> keys_of_table(std::string_view table) {
  std::vector<std::string> keys;
  for (const SpecField& f : spec_fields())
    if (f.table == table) keys.emplace_back(f.key);
  return keys;
}

std::vector<std::string> table_names() {
  std::vector<std::string> names;
  for (const SpecTable& t : spec_tables()) names.emplace_back(t.name);
  return names;
}

const SpecField* find_field(std::string_view table, std::string_view key) {
  for (const SpecField& f : spec_fields())
    if (f.table == table && f.key == key) return &f;
  return nullptr;
}

bool is_table_name(std::string_view name) {
  const std::vector<SpecTable>& tables = spec_tables();
  return std::any_of(tables.begin(), tables.end(), [&](const SpecTable& t) { return t.name == name; });
}

std::string toml_double(double v);

// How a TOML node looks, for type errors.
std::string describe(const toml::node& n) {
  if (auto s = n.value_exact<std::string>()) return fmt::format("the string \"{}\"", *s);
  if (n.is_boolean()) return fmt::format("the boolean {}", *n.value_exact<bool>());
  if (n.is_integer()) return fmt::format("the integer {}", *n.value_exact<std::int64_t>());
  if (n.is_floating_point()) return fmt::format("the number {}", toml_double(*n.value_exact<double>()));
  if (n.is_array()) return "an array";
  if (n.is_table()) return "a table";
  return "a date/time";
}

std::string join(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

// Escapes a string as a TOML basic string, quotes included.
std::string toml_string(std::string_view s) {
  std::string out = "\"";
  for (const char c : s) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\t': out += "\\t"; break;
      case '\r': out += "\\r"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
          out += fmt::format("\\u{:04X}", static_cast<unsigned>(static_cast<unsigned char>(c)));
        else
          out += c;
    }
  }
  return out + "\"";
}

// Shortest decimal that reads back to the same double, always a TOML float:
// plain below 1e6 and from 1e-3 (0.19, 100000.0), else scientific (4e9, 7.07e-4).
std::string toml_double(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  const double a = std::fabs(v);
  if (a == 0 || (a >= 1e-3 && a < 1e6)) {
    std::string s = fmt::format("{}", v);  // shortest round-trip
    if (s.find_first_of(".e") == std::string::npos) s += ".0";
    return s;
  }
  std::string s;
  for (int digits = 0; digits <= 17; ++digits) {
    s = fmt::format("{:.{}e}", v, digits);
    if (std::strtod(s.c_str(), nullptr) == v) break;
  }
  // "4e+09" -> "4e9", "7.07e-04" -> "7.07e-4": TOML takes both, the short one reads better.
  const std::size_t e = s.find('e');
  std::string mantissa = s.substr(0, e), exponent = s.substr(e + 1);
  const bool negative = exponent[0] == '-';
  exponent = exponent.substr(1);
  exponent.erase(0, std::min(exponent.find_first_not_of('0'), exponent.size() - 1));
  return mantissa + "e" + (negative ? "-" : "") + exponent;
}

// The value a field holds, as TOML.
std::string toml_value(const SpecFieldRef& ref) {
  return std::visit(
      [](auto* p) -> std::string {
        using T = std::remove_pointer_t<decltype(p)>;
        if constexpr (std::is_same_v<T, double>) return toml_double(*p);
        else if constexpr (std::is_same_v<T, int>) return fmt::format("{}", *p);
        else if constexpr (std::is_same_v<T, std::uint64_t>) return fmt::format("{}", *p);
        else if constexpr (std::is_same_v<T, std::string>) return toml_string(*p);
        else if constexpr (std::is_same_v<T, std::vector<double>>) {
          std::string s = "[";
          for (std::size_t i = 0; i < p->size(); ++i) s += (i ? ", " : "") + toml_double((*p)[i]);
          return s + "]";
        } else return toml_string(contact_law_name(*p));
      },
      ref);
}

// The [material.<law>] table of spec's law: its parameters with unit,
// meaning and valid range in comments.
std::string law_table(LabSpec& spec) {
  const ContactLawEntry& law = *spec.material.law;
  std::string out = fmt::format("\n# the parameters of the contact law: {}\n[material.{}]\n", contact_law_summary(law), law.name);
  for (const LawParameter& p : law.parameters) {
    const std::string line = fmt::format("{} = {}", p.key, toml_double(parameter_value(spec.material.grain, p)));
    out += fmt::format("{:<36} # {}{}, {}\n", line, *p.unit ? fmt::format("{}, ", p.unit) : "", p.meaning, p.rule);
  }
  return out;
}

std::string write_toml(const LabSpec& spec_in, bool comments) {
  LabSpec spec = spec_in;  // the field refs need a mutable spec
  std::string out;
  if (comments) {
    out += fmt::format(
        "# grainlab {} run. SI units throughout (m, kg, s, N, Pa).\n"
        "# Every key is optional: a key left out keeps the value shown here.\n"
        "# Run it with: grainlab run FILE\n\n",
        spec.test);
  }
  std::string_view table = "";
  const std::vector<SpecTable>& tables = spec_tables();
  for (const SpecField& f : spec_fields()) {
    const auto t = std::find_if(tables.begin(), tables.end(), [&](const SpecTable& x) { return x.name == f.table; });
    // The commented defaults leave out the tables only another test reads
    // (config.toml keeps every key: resuming compares them all), and show
    // the chosen law's parameters in its own table.
    if (comments && t != tables.end() && !t->test.empty() && t->test != spec.test) continue;
    if (comments && f.parameter) continue;
    if (f.table != table) {
      if (comments && table == "material") out += law_table(spec);
      table = f.table;
      out += "\n";
      if (comments) out += fmt::format("# {}\n", t->doc);
      out += fmt::format("[{}]\n", table);
    }
    const std::string line = fmt::format("{} = {}", f.key, toml_value(f.ref(spec)));
    if (comments)
      out += fmt::format("{:<36} # {}\n", line, f.doc);
    else
      out += line + "\n";
  }
  return out;
}

// Throws the InputError for an impossible value of `key`.
[[noreturn]] void impossible(const std::string& source, const LineMap* lines, std::string_view key,
                             const std::string& value, std::string_view rule) {
  int line = 0;
  if (lines) {
    const auto it = lines->find(key);
    if (it != lines->end()) line = it->second;
  }
  const char* origin = lines && line == 0 ? " (the file does not set it: this is the default or the preset's value)" : "";
  input_error("{}: {} = {} is impossible: it must be {}. Set {} in the config{}.", where(source, line), key, value,
              rule, key, origin);
}

void validate_spec(const LabSpec& spec_in, const std::string& source, const LineMap* lines) {
  LabSpec spec = spec_in;
  // Every number must be finite (TOML allows inf and nan).
  for (const SpecField& f : spec_fields()) {
    const SpecFieldRef ref = f.ref(spec);
    if (const auto* p = std::get_if<double*>(&ref); p && !std::isfinite(**p))
      impossible(source, lines, f.dotted(), toml_double(**p), "a finite number");
    if (const auto* p = std::get_if<std::vector<double>*>(&ref))
      for (const double x : **p)
        if (!std::isfinite(x)) impossible(source, lines, f.dotted(), toml_value(ref), "a list of finite numbers");
  }
  const auto need = [&](bool ok, std::string_view key, double value, std::string_view rule) {
    if (!ok) impossible(source, lines, key, fmt::format("{}", value), rule);
  };
  const auto need_s = [&](bool ok, std::string_view key, const std::string& value, std::string_view rule) {
    if (!ok) impossible(source, lines, key, toml_string(value), rule);
  };

  const std::vector<std::string> tests = lab_test_names();
  need_s(std::find(tests.begin(), tests.end(), spec.test) != tests.end(), "test", spec.test,
         fmt::format("one of the lab tests: \"{}\"", fmt::join(tests, "\", \"")));

  const GrainsSpec& g = spec.grains;
  const bool known_class =
      std::find(kGrainClasses.begin(), kGrainClasses.end(), g.preset) != kGrainClasses.end();
  need_s(known_class || (g.preset.empty() && !g.folder.empty()), "grains.preset", g.preset,
         "one of \"glass-beads\", \"rounded\", \"sub-angular\", \"angular\" (polytopes) or \"sh-ottawa\", "
         "\"sh-river\", \"sh-limestone\" (spherical-harmonic sands)");
  if (!g.folder.empty()) {
    std::error_code ec;
    if (!std::filesystem::is_directory(g.folder, ec)) {
      int line = 0;
      if (lines)
        if (const auto it = lines->find("grains.folder"); it != lines->end()) line = it->second;
      input_error("{}: grains.folder = {}: no such folder (relative paths start at the working directory {}). "
                  "Give the folder that holds the grain meshes (STL, OBJ, PLY), or remove grains.folder to "
                  "generate grains from grains.preset.",
                  where(source, line), toml_string(g.folder), std::filesystem::current_path(ec).string());
    }
  }
  need(g.shapes >= 1, "grains.shapes", g.shapes, "at least 1 (distinct grain shapes)");
  need(g.faces >= 100, "grains.faces", g.faces, "at least 100 (faces per grain shape; the paper's grains have ~2000)");
  need(g.d_min > 0, "grains.d_min", g.d_min, "> 0 (m; 0.707 mm is 0.707e-3)");
  need(g.d_max > g.d_min, "grains.d_max", g.d_max,
       fmt::format("larger than grains.d_min = {} (m; the sieve range is [d_min, d_max])", g.d_min));
  need(g.convexity >= kMinConvexity && g.convexity <= 1, "grains.convexity", g.convexity,
       fmt::format("in [{}, 1] (volume over convex hull volume; 1 = convex grains)", kMinConvexity));
  if (!g.scan.empty()) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(std::filesystem::path(g.scan) / "grains.csv", ec)) {
      int line = 0;
      if (lines)
        if (const auto it = lines->find("grains.scan"); it != lines->end()) line = it->second;
      input_error("{}: grains.scan = {}: no grains.csv there (relative paths start at the working directory {}). "
                  "Give the folder that `grainlab ct segment IMAGE --out DIR` wrote, or remove grains.scan.",
                  where(source, line), toml_string(g.scan), std::filesystem::current_path(ec).string());
    }
  }
  need_s(g.scan_border == "drop" || g.scan_border == "keep", "grains.scan_border", g.scan_border,
         "one of \"drop\", \"keep\"");
  need_s(g.representation == "auto" || g.representation == "hull" || g.representation == "concave",
         "grains.representation", g.representation, "one of \"auto\", \"hull\", \"concave\"");

  const MaterialSpec& ms = spec.material;
  const std::vector<std::string> sands = sand_preset_names();
  need_s(ms.preset.empty() || std::find(sands.begin(), sands.end(), ms.preset) != sands.end(), "material.preset",
         ms.preset, fmt::format("one of {} or \"\" (no preset)", join(sands)));
  const Material& m = ms.grain;
  need(m.density > 0, "material.density", m.density, "> 0 (kg/m^3; quartz is 2650)");
  need(m.friction >= 0, "material.friction", m.friction, ">= 0");
  // The law's own parameters by its rules, then every other law's (a file may switch laws).
  const auto need_law = [&](const ContactLawEntry& law) {
    for (const LawParameter& p : law.parameters)
      need(p.accepts(parameter_value(m, p)), fmt::format("material.{}", p.key), parameter_value(m, p),
           parameter_rule(p));
  };
  need_law(*ms.law);
  for (const ContactLawEntry& law : contact_laws()) need_law(law);
  need(ms.wall_friction >= 0, "material.wall_friction", ms.wall_friction, ">= 0");

  const BoxSpec& b = spec.box;
  need(b.length > 0, "box.length", b.length, "> 0 (m)");
  need(b.width > 0, "box.width", b.width, "> 0 (m)");
  need(b.height > 0, "box.height", b.height, "> 0 (m)");
  need(b.gap >= 0, "box.gap", b.gap, ">= 0 (m)");
  need(b.gap < b.height, "box.gap", b.gap, fmt::format("smaller than box.height = {} (m)", b.height));

  const SpecimenSpec& sp = spec.specimen;
  need(sp.relative_density >= 0 && sp.relative_density <= 1, "specimen.relative_density", sp.relative_density,
       "in [0, 1] (a fraction: 96 % is 0.96)");
  need(sp.e_min > 0, "specimen.e_min", sp.e_min, "> 0");
  need(sp.e_max > sp.e_min, "specimen.e_max", sp.e_max,
       fmt::format("larger than specimen.e_min = {}", sp.e_min));
  need(sp.tolerance > 0, "specimen.tolerance", sp.tolerance, "> 0 (in void ratio)");
  need(sp.relative_density_tolerance > 0 && sp.relative_density_tolerance < 1, "specimen.relative_density_tolerance",
       sp.relative_density_tolerance, "in (0, 1) (a fraction of the index range: 5 % is 0.05)");
  need_s(sp.indices == "own" || sp.indices == "lab", "specimen.indices", sp.indices,
         "\"own\" (the grains' own index void ratios, measured) or \"lab\" (specimen.e_min/e_max)");
  need(sp.own_e_min >= 0, "specimen.own_e_min", sp.own_e_min, ">= 0 (0: the run measures it)");
  need(sp.own_e_max >= 0, "specimen.own_e_max", sp.own_e_max, ">= 0 (0: the run measures it)");
  need((sp.own_e_min > 0) == (sp.own_e_max > 0), "specimen.own_e_max", sp.own_e_max,
       "given together with specimen.own_e_min (both from `grainlab grains index`), or both 0 to measure them");
  need(sp.own_e_max == 0 || sp.own_e_max > sp.own_e_min, "specimen.own_e_max", sp.own_e_max,
       fmt::format("larger than specimen.own_e_min = {}", sp.own_e_min));
  need(sp.deposition_friction >= 0 || sp.deposition_friction == -1, "specimen.deposition_friction",
       sp.deposition_friction, ">= 0, or -1 to have it chosen by bisection");

  const ConsolidationSpec& c = spec.consolidation;
  need(c.normal_stress > 0, "consolidation.normal_stress", c.normal_stress, "> 0 (Pa; 100 kPa is 100e3)");
  need(c.tolerance > 0 && c.tolerance < 1, "consolidation.tolerance", c.tolerance,
       "in (0, 1) (relative: 1 % is 0.01)");
  need(c.max_unbalanced > 0, "consolidation.max_unbalanced", c.max_unbalanced, "> 0");

  // Each registered test's own keys (lab/spec_keys.h), in registration order.
  const SpecNeed need_test = [&](bool ok, std::string_view key, SpecFieldRef value, std::string_view rule) {
    if (ok) return;
    const std::string shown = std::visit(
        [&](auto* p) -> std::string {
          using T = std::remove_pointer_t<decltype(p)>;
          if constexpr (std::is_same_v<T, double> || std::is_same_v<T, int> || std::is_same_v<T, std::uint64_t>)
            return fmt::format("{}", *p);
          else if constexpr (std::is_same_v<T, std::string>) return toml_string(*p);
          else return toml_value(value);
        },
        value);
    impossible(source, lines, key, shown, rule);
  };
  const LabTestEntry* entry = nullptr;
  for (const LabTestEntry& e : lab_test_entries()) {
    if (e.name == spec.test) entry = &e;
    if (e.keys.validate) e.keys.validate(spec, need_test);
  }

  const NumericsSpec& nu = spec.numerics;
  need(nu.time_step >= 0, "numerics.time_step", nu.time_step, ">= 0 (s; 0 picks a safe step)");
  need(nu.time_step_fraction > 0 && nu.time_step_fraction <= 1, "numerics.time_step_fraction",
       nu.time_step_fraction, "in (0, 1]");
  need(nu.density_scaling >= 0, "numerics.density_scaling", nu.density_scaling, ">= 0 (0 = automatic)");
  need(nu.inertial_number > 0, "numerics.inertial_number", nu.inertial_number, "> 0 (quasi-static: below 1e-3)");
  need(nu.threads >= 0, "numerics.threads", nu.threads, ">= 0 (0 = automatic)");

  const OutputSpec& o = spec.output;
  need_s(!o.folder.empty(), "output.folder", o.folder, "a folder name, not empty");
  // Samples every strain_interval up to the test's final strain (its final_strain_key).
  const SpecField* end = nullptr;
  for (const SpecField& f : spec_fields())
    if (entry && f.dotted() == entry->keys.final_strain_key) end = &f;
  const double final_strain = end ? *std::get<double*>(end->ref(spec)) : INFINITY;
  need(o.strain_interval > 0 && o.strain_interval <= final_strain, "output.strain_interval", o.strain_interval,
       end ? fmt::format("> 0 and at most {} = {}", end->dotted(), final_strain) : std::string("> 0"));
  need(o.checkpoint_interval > 0, "output.checkpoint_interval", o.checkpoint_interval, "> 0 (s of wall-clock time)");
  need(o.snapshot_interval >= 0, "output.snapshot_interval", o.snapshot_interval,
       ">= 0 (shear strain between ParaView snapshots; 0 = start and end of shear only)");

  need(spec.seed <= static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max()), "seed",
       static_cast<double>(spec.seed), "at most 2^63 - 1 (a TOML integer)");
}

// Stores the TOML value `n` into the field `ref`, or throws a type error.
void assign(const SpecField& f, const SpecFieldRef& ref, const toml::node& n, const std::string& source) {
  const int line = line_of(n.source());
  const std::string key = f.dotted();
  const auto wrong = [&](std::string_view expected) {
    input_error("{}: {} expects {}, but the file gives {}. ({}: {}.)", where(source, line), key, expected,
                describe(n), key, std::string(f.doc));
  };
  std::visit(
      [&](auto* p) {
        using T = std::remove_pointer_t<decltype(p)>;
        if constexpr (std::is_same_v<T, double>) {
          if (n.is_integer()) *p = static_cast<double>(*n.value_exact<std::int64_t>());
          else if (n.is_floating_point()) *p = *n.value_exact<double>();
          else wrong("a number in SI units (e.g. 100e3, not \"100 kPa\")");
        } else if constexpr (std::is_same_v<T, int>) {
          if (!n.is_integer()) wrong("a whole number (e.g. 500, not 500.0)");
          const std::int64_t v = *n.value_exact<std::int64_t>();
          if (v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max())
            input_error("{}: {} = {} is out of range; use a value below 2^31.", where(source, line), key, v);
          *p = static_cast<int>(v);
        } else if constexpr (std::is_same_v<T, std::uint64_t>) {
          if (!n.is_integer()) wrong("a whole number >= 0");
          const std::int64_t v = *n.value_exact<std::int64_t>();
          if (v < 0) input_error("{}: {} = {} is negative; use a whole number >= 0.", where(source, line), key, v);
          *p = static_cast<std::uint64_t>(v);
        } else if constexpr (std::is_same_v<T, std::string>) {
          if (!n.is_string()) wrong("a string in quotes");
          *p = *n.value_exact<std::string>();
        } else if constexpr (std::is_same_v<T, std::vector<double>>) {
          const toml::array* a = n.as_array();
          if (!a) wrong("a list of numbers in SI units (e.g. [200e3, 400e3])");
          p->clear();
          for (const toml::node& x : *a) {
            if (x.is_integer()) p->push_back(static_cast<double>(*x.value_exact<std::int64_t>()));
            else if (x.is_floating_point()) p->push_back(*x.value_exact<double>());
            else wrong(fmt::format("a list of numbers in SI units (e.g. [200e3, 400e3]); one entry is {}", describe(x)));
          }
        } else {
          if (!n.is_string()) wrong("a string in quotes");
          try {
            *p = parse_contact_law(*n.value_exact<std::string>());
          } catch (const InputError& e) {
            input_error("{}: {}: {}.", where(source, line), key, e.what());
          }
        }
      },
      ref);
}

}  // namespace

// Refuses a key longer than kMaxKeyLength or a string longer than
// kMaxStringLength (a path's limit, PATH_MAX), quoting only their start: every
// later message that echoes a value is then bounded too.
constexpr std::size_t kMaxKeyLength = 100, kMaxStringLength = 4096;

void check_lengths(const toml::node& node, const std::string& source) {
  if (const toml::table* t = node.as_table()) {
    for (const auto& [k, n] : *t) {
      if (k.str().size() > kMaxKeyLength)
        input_error("{}: a key of {} characters ('{}'), longer than any grainlab key ({} at most); fix the key",
                    where(source, line_of(k.source())), k.str().size(), excerpt(k.str(), 40), kMaxKeyLength);
      check_lengths(n, source);
    }
  } else if (const toml::array* a = node.as_array()) {
    for (const toml::node& n : *a) check_lengths(n, source);
  } else if (const auto* s = node.as_string(); s && s->get().size() > kMaxStringLength) {
    input_error("{}: a string of {} characters (\"{}\"), longer than the {} a value (a path included) can be; "
                "fix the value",
                where(source, line_of(node.source())), s->get().size(), excerpt(s->get(), 40), kMaxStringLength);
  }
}

// ---------------------------------------------------------------------------
// Public API.

LabSpec parse_config(std::string_view toml_text, const std::string& source_name) {
  toml::table root;
  try {
    root = toml::parse(toml_text, source_name);
  } catch (const toml::parse_error& e) {
    input_error("{}: TOML syntax error: {}. Fix the file at that place (TOML is `key = value` lines under "
                "[table] headers; strings go in double quotes).",
                where(source_name, static_cast<int>(e.source().begin.line), static_cast<int>(e.source().begin.column)),
                excerpt(e.description(), 300));
  }
  check_lengths(root, source_name);

  // Match every key in the file to a field; refuse what is not a field.
  std::vector<std::pair<const SpecField*, const toml::node*>> given;
  LineMap lines;
  const auto take = [&](const SpecField* f, const toml::node& n) {
    // A law's parameter may come twice: flat and in its law's table, or in two laws' tables that share it.
    if (const auto it = lines.find(f->dotted()); it != lines.end()) {
      const int here = line_of(n.source());
      input_error("{}: {} is given twice (also on line {}); give it once.",
                  where(source_name, std::max(here, it->second)), f->dotted(), std::min(here, it->second));
    }
    given.emplace_back(f, &n);
    lines[f->dotted()] = line_of(n.source());
  };
  // [material.<law>]: the keys of that law's parameters.
  const auto take_law_table = [&](const std::string& law_name, const toml::node& node) {
    const ContactLawEntry* law = find_law(law_name);
    if (!law)
      input_error("{}: unknown table [material.{}]: a law's parameters go in [material.<law>], <law> one of {}.",
                  where(source_name, line_of(node.source())), law_name, contact_law_names());
    std::vector<std::string> valid;
    for (const LawParameter& p : law->parameters) valid.emplace_back(p.key);
    for (const auto& [k, n] : *node.as_table()) {
      const std::string key(k.str());
      if (std::find(valid.begin(), valid.end(), key) == valid.end())
        input_error("{}: unknown key '{}' in [material.{}].{} The parameters of contact law \"{}\": {}.",
                    where(source_name, line_of(k.source())), key, law_name, suggestion(key, valid), law_name,
                    join(valid));
      take(find_field("material", key), n);
    }
  };
  for (const auto& [key, node] : root) {
    const std::string name(key.str());
    const int line = line_of(key.source());
    if (is_table_name(name)) {
      const toml::table* t = node.as_table();
      if (!t)
        input_error("{}: '{}' must be a table (a [{}] header followed by its keys), but the file gives {}.",
                    where(source_name, line), name, name, describe(node));
      for (const auto& [k, n] : *t) {
        const std::string sub(k.str());
        if (const SpecField* f = find_field(name, sub)) {
          take(f, n);
          continue;
        }
        if (name == "material" && n.is_table()) {
          take_law_table(sub, n);
          continue;
        }
        const std::vector<std::string> valid = keys_of_table(name);
        input_error("{}: unknown key '{}.{}'.{} Valid keys in [{}]: {}.", where(source_name, line_of(k.source())),
                    name, sub, suggestion(sub, valid), name, join(valid));
      }
    } else if (const SpecField* f = find_field("", name)) {
      take(f, node);
    } else if (node.is_table()) {
      input_error("{}: unknown table [{}].{} Valid tables: {}.", where(source_name, line), name,
                  suggestion(name, table_names()), join(table_names()));
    } else {
      // A table key written at the top level (after no header, or before the first one)?
      std::string hint;
      for (const SpecField& f : spec_fields())
        if (!f.table.empty() && f.key == name) {
          hint = fmt::format(" It belongs in the [{}] table: put it below the [{}] header.", f.table, f.table);
          break;
        }
      if (hint.empty()) {
        std::vector<std::string> top = table_names();
        for (const SpecField& f : spec_fields())
          if (f.table.empty()) top.emplace_back(f.key);
        hint = suggestion(name, top) + fmt::format(" Top-level keys: test, seed; tables: {}.", join(table_names()));
      }
      input_error("{}: unknown key '{}'.{}", where(source_name, line), name, hint);
    }
  }

  // The sand preset first, then every other key on top of it.
  LabSpec spec;
  for (const auto& [f, n] : given) {
    if (f->table != "material" || f->key != "preset") continue;
    std::string preset;
    assign(*f, SpecFieldRef(&preset), *n, source_name);
    if (!preset.empty()) {
      const std::vector<std::string> sands = sand_preset_names();
      if (std::find(sands.begin(), sands.end(), preset) == sands.end())
        input_error("{}: material.preset = \"{}\" is not a sand preset.{} Use one of {}, or \"\" for none.",
                    where(source_name, line_of(n->source())), preset, suggestion(preset, sands), join(sands));
      apply_sand_preset(spec, preset);
    }
    spec.material.preset = preset;
  }
  for (const auto& [f, n] : given) {
    if (f->table == "material" && f->key == "preset") continue;
    assign(*f, f->ref(spec), *n, source_name);
  }
  validate_spec(spec, source_name, &lines);
  return spec;
}

LabSpec load_config(const std::filesystem::path& file) {
  std::error_code ec;
  if (!std::filesystem::exists(file, ec))
    input_error("config file '{}' does not exist (working directory: {}). Check the path, or write a default "
                "config with `grainlab run --print-defaults > {}` and edit it.",
                file.string(), std::filesystem::current_path(ec).string(), file.string());
  if (std::filesystem::is_directory(file, ec))
    input_error("config file '{}' is a folder; give the path of a .toml file.", file.string());
  // A config is a few kilobytes; 4 MiB bounds what a wrong path (/dev/zero, a mesh) can make it allocate.
  return parse_config(read_bounded_file(file, 4 * kMiB, "config file"), file.string());
}

void validate(const LabSpec& spec, const std::string& source_name) {
  validate_spec(spec, source_name, nullptr);
}

std::string default_config_toml(const std::string& test, ContactLaw law) {
  LabSpec spec;
  spec.test = test;
  spec.material.law = law;
  spec.output.folder = "runs/" + test;  // runs/direct_shear, runs/oedometer, runs/triaxial
  std::replace(spec.output.folder.begin(), spec.output.folder.end(), '-', '_');
  validate_spec(spec, "the defaults", nullptr);  // an unknown test name
  return write_toml(spec, true);
}

std::string to_toml(const LabSpec& spec) { return write_toml(spec, false); }

std::vector<std::string> config_differences(const LabSpec& a_in, const LabSpec& b_in) {
  LabSpec a = a_in, b = b_in;
  std::vector<std::string> diff;
  for (const SpecField& f : spec_fields()) {
    const bool same = std::visit(
        [&](auto* pa) {
          using P = decltype(pa);
          P pb = std::get<P>(f.ref(b));
          if constexpr (std::is_same_v<P, double*>) {
            return std::bit_cast<std::uint64_t>(*pa) == std::bit_cast<std::uint64_t>(*pb);
          } else {
            return *pa == *pb;
          }
        },
        f.ref(a));
    if (!same) diff.push_back(f.dotted());
  }
  return diff;
}

}  // namespace grainlab
