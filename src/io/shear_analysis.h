// The micromechanics columns a direct shear run appends to every row of
// series.csv, and the shear band they rest on: the test's numbers handed to
// the analysis layer (analysis/shear_sample.h defines the columns,
// analysis/band_analysis.h the band), which computes them; io only names and
// orders them. The reference is LabTest::reference(), the grains
// at the start of shear.
#pragma once

#include "analysis/band_analysis.h"
#include "dynamics/state.h"
#include "lab/lab_test.h"

#include <string>
#include <vector>

namespace grainlab {

// The test's shear reference as a State (bodies only); empty before shear.
State shear_reference_state(const LabTest& test);

// The test's inputs to the band rules (LabTest::band_geometry()).
analysis::BandInputs band_inputs(const LabTest& test);

// The profile and band of the test's current state (analysis/band_analysis.h).
using BandAnalysis = analysis::BandResult;
BandAnalysis analyse_band(const LabTest& test, const State& reference);

// The analysis columns, in order (names in analysis/shear_sample.h).
const std::vector<std::string>& shear_analysis_columns();

// Their values for the test's current state (shear_analysis_columns() order).
std::vector<double> shear_analysis_values(const LabTest& test);

// Sets the test's sample observer to shear_analysis_values: call before the
// run starts (and the same on a resumed run, so that its rows match).
void observe_shear_analysis(LabTest& test);

}  // namespace grainlab
