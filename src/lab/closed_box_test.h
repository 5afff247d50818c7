// A lab test whose specimen is prepared by the direct shear protocol's
// deposit, compact and consolidate phases (lab/direct_shear.h: the same
// code, density target and checks) in the shear box with its gap closed, so
// that its eight side slabs form one rigid ring, and then loaded its own way:
// the oedometer (lab/oedometer.h) and the triaxial test (lab/triaxial.h).
// It holds that preparation, the sample observer and the byte helpers both
// tests use; a test adds its phases after the preparation's.
#pragma once

#include "core/bytes.h"
#include "lab/direct_shear.h"
#include "lab/lab_test.h"

#include <string>
#include <vector>

namespace grainlab {

class ClosedBoxTest : public LabTest {
 public:
  // Builds the preparation (test "direct-shear", box.gap 0, ending after consolidation).
  explicit ClosedBoxTest(const DirectShearSpec& spec);
  ClosedBoxTest(const ClosedBoxTest&) = delete;
  ClosedBoxTest& operator=(const ClosedBoxTest&) = delete;

  const DirectShearSpec& spec() const override { return spec_; }
  World& world() override { return prep_.world(); }
  const World& world() const override { return prep_.world(); }
  double time_step() const override { return prep_.time_step(); }
  std::vector<std::string> series_columns() const override;
  void set_sample_observer(std::vector<std::string> columns, SampleObserver observer) override;

  // The preparation (the direct shear protocol ending after consolidation).
  const DirectShearTest& preparation() const { return prep_; }

 protected:
  // The test's own series columns (the observer's follow).
  virtual const std::vector<std::string>& own_columns() const = 0;
  // Appends the observer's values to a row of own_columns().
  void observe(std::vector<double>& row) const;
  // The preparation's run.json values: group "preparation" and the grain size.
  std::vector<SummaryValue> preparation_summary() const;
  // The preparation's protocol bytes, length first.
  void save_preparation(ByteWriter& out) const;
  void load_preparation(ByteReader& in);
  // Grain states (the reference of a loading phase).
  static void save_bodies(ByteWriter& out, const std::vector<BodyState>& bodies);
  static std::vector<BodyState> load_bodies(ByteReader& in);

  DirectShearSpec spec_;
  DirectShearTest prep_;

 private:
  std::vector<std::string> observer_columns_;
  SampleObserver observer_;
};

}  // namespace grainlab
