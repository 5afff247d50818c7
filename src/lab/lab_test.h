// LabTest: what io and apps see of a virtual lab test (direct shear,
// oedometer, triaxial), so that they never name a concrete test.
//
// A test owns its World and steps it in phases (preparation, then a measured
// loading phase). It records one series row per sample during loading, keeps
// the grains at the start of loading as the reference of displacements and
// rotations, summarises its results as named numbers, and saves / restores its
// own protocol state (core/bytes.h) next to the World's State in a
// checkpoint: restoring both continues the run bit for bit.
//
// Tests register by name in lab/lab_registry.cpp (one line each) and are made
// by make_lab_test(name, spec).
#pragma once

#include "dynamics/world.h"
#include "lab/lab_spec.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace grainlab {

// One named result of a test: run.json writes it as json[group][key] (or
// json[key] when group is empty).
struct SummaryValue {
  std::string group;  // e.g. "peaks", "final", "preparation"; "" = top level
  std::string key;    // e.g. "friction_angle_deg"
  double value = 0;
};

// Where io bins the grains to find a shear band: layers across `axis` (a
// world-frame height range) of displacement along `direction`.
struct BandGeometry {
  double z_min = 0, z_max = 0;  // m, reference heights spanned (floor, boundary at the start of loading)
  double layer = 0;             // m, layer thickness (about one grain diameter)
  Vec3 direction = Vec3::UnitX();  // the imposed displacement's direction
  double strain = 0;            // imposed shear strain since the start of loading
  double length = 0;            // m, over which it is imposed: the displacement is strain x length
};

// Pure: what every test has (its spec and World, the steps, the phases,
// loading, its checkpoint bytes). The rest has a default for a test that
// does not care (no series, no summary, no notes); PreparedTest gives the
// preparation's where there is one.
class LabTest {
 public:
  // Appends its own values to every sample row (a higher layer's analysis).
  using SampleObserver = std::function<std::vector<double>(const LabTest&)>;

  virtual ~LabTest() = default;

  // The run's settings.
  virtual const LabSpec& spec() const = 0;
  // The simulated World (read the State and Model; a restore writes the State).
  virtual World& world() = 0;
  virtual const World& world() const = 0;
  // Time step of every step (s).
  virtual double time_step() const = 0;

  // Advances by up to max_steps steps; returns early at a phase change and
  // after recording a sample. False once the test is done. Throws RunError
  // if a phase misses its target or does not converge.
  virtual bool advance(int max_steps) = 0;
  // Current phase: an index that grows as the test goes on, and its name.
  virtual int phase_index() const = 0;
  virtual std::string phase_name() const = 0;
  // True in the measured loading phase (samples are taken there).
  virtual bool loading() const = 0;
  virtual bool done() const = 0;
  // Step at which loading began (0 before).
  virtual std::int64_t loading_start_step() const = 0;
  // Loading progress (direct shear: shear strain), its final value and what
  // it measures, for messages ("shear strain").
  virtual double progress() const = 0;
  virtual double final_progress() const { return 1; }
  virtual std::string progress_label() const { return "progress"; }
  // One progress line of current measurements (e.g. "strain 0.0100  stress ratio 0.550 ...").
  virtual std::string status_line() const { return ""; }
  // A line worth printing as the current phase begins ("" if none).
  virtual std::string phase_note() const { return ""; }
  // The final results in one sentence.
  virtual std::string result_line() const { return "done"; }

  // Series: column names (with units; the observer's last) and rows; none by default.
  virtual std::vector<std::string> series_columns() const { return {}; }
  virtual const std::vector<std::vector<double>>& series() const;
  // Sets the sample observer (before the first sample; the same on a resumed
  // run); a test without series takes no samples and ignores it.
  virtual void set_sample_observer(std::vector<std::string> /*columns*/, SampleObserver /*observer*/) {}
  // The grains at the start of loading (empty before, and by default).
  virtual const std::vector<BodyState>& reference() const;
  // Named results (run.json), valid at any time (zeros before loading); none by default.
  virtual std::vector<SummaryValue> summary() const { return {}; }

  // Specimen volume (m^3) and the stress the boundary holds (Pa) now.
  virtual double specimen_volume() const = 0;
  virtual double boundary_stress() const = 0;
  // Shear band binning of the current state (see BandGeometry), for a test
  // that imposes a displacement (the direct shear; the oedometer and the
  // triaxial test give theirs for the record); none by default: io then bins
  // the whole specimen (whole_specimen_band_geometry).
  virtual std::optional<BandGeometry> band_geometry() const { return std::nullopt; }

  // The protocol's own state (the World's State is saved separately).
  virtual std::vector<std::uint8_t> save() const = 0;
  // Restores it; call after restoring the World's State. Throws InputError if the bytes are bad.
  virtual void load(std::span<const std::uint8_t> bytes) = 0;
};

class SpecimenPreparation;

// The band binning of a test without one (LabTest::band_geometry): from the
// floor to the highest grain's top now, layers of the grains' mean
// volume-equivalent diameter, no imposed strain.
BandGeometry whole_specimen_band_geometry(const World& world);

// Makes the test registered under `name` ("direct-shear"); InputError naming
// the registered tests if there is none. `prepared` (may be null): a
// preparation of `spec` in its own box (the preparation search's trial),
// which a test prepared in that box goes on from; a test prepared in
// another box (the closed box of lab/closed_box_test.h) prepares its own.
std::unique_ptr<LabTest> make_lab_test(const std::string& name, const LabSpec& spec);
std::unique_ptr<LabTest> make_lab_test(const std::string& name, const LabSpec& spec,
                                       std::unique_ptr<SpecimenPreparation> prepared);
// Names of the registered tests.
std::vector<std::string> lab_test_names();

}  // namespace grainlab
