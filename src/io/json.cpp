// run.json helpers: spec_to_json walks the config key list (spec_fields.h),
// so run.json and the TOML config always name the same keys.
#include "io/json.h"

#include "core/bounded_read.h"
#include "core/error.h"
#include "core/atomic_file.h"
#include "io/spec_fields.h"

#include <fstream>
#include <sstream>
#include <variant>

namespace grainlab {

nlohmann::json spec_to_json(const LabSpec& spec_in) {
  LabSpec spec = spec_in;  // the field refs need a mutable spec
  nlohmann::json j = nlohmann::json::object();
  for (const SpecField& f : spec_fields()) {
    nlohmann::json& slot = f.table.empty() ? j[std::string(f.key)] : j[std::string(f.table)][std::string(f.key)];
    std::visit(
        [&](auto* p) {
          using T = std::remove_pointer_t<decltype(p)>;
          if constexpr (std::is_same_v<T, ContactLaw>) slot = contact_law_name(*p);
          else slot = *p;
        },
        f.ref(spec));
  }
  return j;
}

void write_json_file(const std::filesystem::path& path, const nlohmann::json& j) {
  write_file_atomically(path, j.dump(2) + "\n");
}

nlohmann::json read_json_file(const std::filesystem::path& path) {
  const std::string text = read_bounded_file(path, 256 * kMiB, "JSON file");
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    input_error("'{}' is not valid JSON (byte {}): {}", path.string(), e.byte, e.what());
  }
}

}  // namespace grainlab
