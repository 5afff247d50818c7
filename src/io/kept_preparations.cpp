// Preparations kept as checkpoint files (see kept_preparations.h).
#include "io/kept_preparations.h"

#include "core/bytes.h"
#include "io/checkpoint.h"
#include "io/json.h"
#include "io/preparation_files.h"
#include "lab/preparation.h"

#include <fmt/format.h>

#include <span>
#include <utility>

namespace grainlab {

namespace fs = std::filesystem;

namespace {

std::uint64_t hash_text(const std::string& text) {
  const auto* bytes = reinterpret_cast<const std::uint8_t*>(text.data());
  return fnv1a64(std::span(bytes, text.size()));
}

}  // namespace

std::uint64_t kept_preparation_key(const std::string& name, const LabSpec& prepared) {
  if (name.starts_with("index_"))
    return hash_text(index_cache_key(prepared) + spec_to_json(prepared)["box"].dump() +
                     fmt::format("{:a}", prepared.specimen.deposition_friction));
  LabSpec s = prepared;
  s.output = LabSpec{}.output;
  s.numerics.threads = 0;
  s.reset_test_settings();  // the loading: every test's own table
  return config_hash(s);
}

bool is_kept_preparation_file(const std::string& filename, bool trials_only) {
  if (!filename.ends_with(".bin")) return false;
  return filename.starts_with("trial_") || (!trials_only && filename.starts_with("index_e_m"));
}

void drop_kept_trials(const fs::path& folder) {
  std::error_code ec;
  std::vector<fs::path> trials;
  for (const auto& entry : fs::directory_iterator(folder, ec)) {
    if (is_kept_preparation_file(entry.path().filename().string(), true)) trials.push_back(entry.path());
  }
  for (const fs::path& f : trials) fs::remove(f, ec);
}

KeptPreparations::KeptPreparations(fs::path folder, std::function<bool()> stop)
    : folder_(std::move(folder)), stop_(std::move(stop)) {}

fs::path KeptPreparations::file(const std::string& name) const { return folder_ / (name + ".bin"); }

double KeptPreparations::restore(SpecimenPreparation& preparation, const std::string& name, const LabSpec& prepared) {
  const fs::path f = file(name);
  if (!fs::exists(f)) return -1;
  Checkpoint ck = load_checkpoint(f);
  if (ck.config_hash != kept_preparation_key(name, prepared) || !same_grains(ck, preparation.world().model)) return -1;
  ByteReader in(ck.protocol, f.string());
  const double wall_s = in.f64();
  preparation.world().state = std::move(ck.state);
  preparation.load(in.raw(in.left()));
  return wall_s;
}

void KeptPreparations::keep(const SpecimenPreparation& preparation, const std::string& name, const LabSpec& prepared,
                            double wall_s) {
  ByteWriter protocol;
  protocol.f64(wall_s);
  protocol.raw(preparation.save());
  fs::create_directories(folder_);
  save_checkpoint(file(name), preparation.world().state, protocol.bytes, kept_preparation_key(name, prepared),
                  grains_fingerprint(preparation.world().model));
}

void KeptPreparations::drop(const std::string& name) {
  std::error_code ignored;
  fs::remove(file(name), ignored);
}

}  // namespace grainlab
