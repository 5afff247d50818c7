// Index preparations kept as checkpoint files (see index_preparation_files.h).
#include "io/index_preparation_files.h"

#include "core/bytes.h"
#include "io/checkpoint.h"
#include "io/json.h"
#include "io/preparation_files.h"
#include "lab/direct_shear.h"

#include <fmt/format.h>

#include <span>
#include <utility>

namespace grainlab {

namespace fs = std::filesystem;

std::uint64_t index_preparation_key(const DirectShearSpec& prepared) {
  const nlohmann::json all = spec_to_json(prepared);
  const std::string key = index_cache_key(prepared) + all["box"].dump() +
                          fmt::format("{:a}", prepared.specimen.deposition_friction);
  const auto* bytes = reinterpret_cast<const std::uint8_t*>(key.data());
  return fnv1a64(std::span(bytes, key.size()));
}

IndexPreparationFiles::IndexPreparationFiles(fs::path folder, std::function<bool()> stop)
    : folder_(std::move(folder)), stop_(std::move(stop)) {}

fs::path IndexPreparationFiles::file(const DirectShearSpec& prepared) const {
  return folder_ / fmt::format("index_{}_seed{}.bin", prepared.specimen.deposition_friction == 0 ? "e_min" : "e_max",
                               prepared.seed);
}

double IndexPreparationFiles::restore(DirectShearTest& test, const DirectShearSpec& prepared) {
  const fs::path f = file(prepared);
  if (!fs::exists(f)) return -1;
  Checkpoint ck = load_checkpoint(f);
  if (ck.config_hash != index_preparation_key(prepared)) return -1;
  ByteReader in(ck.protocol, f.string());
  const double wall_s = in.f64();
  test.world().state = std::move(ck.state);
  test.load(in.raw(in.left()));
  return wall_s;
}

void IndexPreparationFiles::keep(const DirectShearTest& test, const DirectShearSpec& prepared, double wall_s) {
  ByteWriter protocol;
  protocol.f64(wall_s);
  protocol.raw(test.save());
  fs::create_directories(folder_);
  save_checkpoint(file(prepared), test.world().state, protocol.bytes, index_preparation_key(prepared));
}

void IndexPreparationFiles::drop(const DirectShearSpec& prepared) {
  std::error_code ignored;
  fs::remove(file(prepared), ignored);
}

}  // namespace grainlab
