// The base of a lab test whose specimen a SpecimenPreparation
// (lab/preparation.h) makes: it owns the preparation (and so the World),
// the run's spec, the sample observer, and the byte helpers the tests'
// checkpoints use; the preparation's measurements are its defaults (status
// line, notes, summary, the cap's stress and the volume below it). A test steps the preparation until it is prepared, then
// loads the specimen its own way: the direct shear (lab/direct_shear.h) in
// the split box, the oedometer and the triaxial test in the box with its gap
// closed (lab/closed_box_test.h).
#pragma once

#include "core/bytes.h"
#include "lab/lab_test.h"
#include "lab/preparation.h"

#include <memory>
#include <string>
#include <vector>

namespace grainlab {

class PreparedTest : public LabTest {
 public:
  // `preparation`: of `spec`'s specimen (its own spec may differ, e.g. in the box's gap).
  PreparedTest(const LabSpec& spec, std::unique_ptr<SpecimenPreparation> preparation);

  const LabSpec& spec() const override { return spec_; }
  World& world() override { return prep_->world(); }
  const World& world() const override { return prep_->world(); }
  double time_step() const override { return prep_->time_step(); }
  std::vector<std::string> series_columns() const override;
  void set_sample_observer(std::vector<std::string> columns, SampleObserver observer) override;
  // The preparation's (lab/preparation.h).
  std::string status_line() const override;
  std::string phase_note() const override;
  std::vector<SummaryValue> summary() const override;
  // Below the cap, over the box's floor (m^3), and the cap's stress (Pa).
  double specimen_volume() const override;
  double boundary_stress() const override;

  // The specimen's preparation.
  const SpecimenPreparation& preparation() const { return *prep_; }

 protected:
  // The test's own series columns (the observer's follow); none by default.
  virtual const std::vector<std::string>& own_columns() const;
  // Appends the observer's values to a row of own_columns().
  void observe(std::vector<double>& row) const;
  // Grain states (the reference of a loading phase).
  static void save_bodies(ByteWriter& out, const std::vector<BodyState>& bodies);
  static std::vector<BodyState> load_bodies(ByteReader& in);

  LabSpec spec_;
  std::unique_ptr<SpecimenPreparation> prep_;

 private:
  std::vector<std::string> observer_columns_;
  SampleObserver observer_;
};

}  // namespace grainlab
