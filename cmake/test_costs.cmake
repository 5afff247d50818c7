# The long tests and what they cost, so that `ctest -j` starts them first.
#
# ctest -j N starts the tests it knows to be the longest first, which keeps
# all N cores busy to the end; it knows a test's cost from
# Testing/Temporary/CTestCostData.txt (written by an earlier ctest in the same
# build folder) or else from the test's COST property. A fresh clone (CI's
# `make test`) has no cost file, and without COST ctest starts the tests in
# the order they were added: the apps layer's preset runs, two minutes each
# for angular grains, came last, and one core ran on alone for minutes.
#
# Each entry: "layer|gtest filter|cost in seconds". A filter is positive
# patterns only, joined by ':'; each test in at most one entry. Costs are
# wall seconds of one test at `ctest -j2` on the 2-core machine
# (docs/performance.md, "Test suite time"); only their order matters.
set(grainlab_test_costs
  "apps|*PresetRun*/direct_shear_angular|120"
  "apps|*PresetRun*/triaxial_angular|110"
  "apps|*PresetRun*/oedometer_angular|100"
  "apps|*PresetRun*/*_rounded:*PresetRun*/*_sub_angular|45"
  "dynamics|RestingContact.FrictionlessFacetedBedComesToRest|49"
  "lab|DenseLooseShear.*:Triaxial.LooseAndDense*:PreparationSearch.BeadsReach*|26"
  "ct|CtSegmentation.AtSeventyTwoVoxels*|23"
  "dynamics|SettlingBed.ConvexGrainsComeToRestInsideTheBox|17"
  "lab|DirectShearProtocol.TinyRun*|16"
  "io|GoldenDirectShear.*|14"
  "apps|RunOutputs.SeriesHas*:Resume.ARunFromAnotherRuns*|11")

# gtest_discover_tests for test_<layer>: one call per entry of the layer
# (its tests with its COST), one for the rest. `ARGN`: properties for all.
function(grainlab_discover_tests layer)
  set(long "")
  foreach(entry IN LISTS grainlab_test_costs)
    string(REPLACE "|" ";" parts "${entry}")
    list(GET parts 0 entry_layer)
    if(NOT entry_layer STREQUAL layer)
      continue()
    endif()
    list(GET parts 1 filter)
    list(GET parts 2 cost)
    gtest_discover_tests(test_${layer} DISCOVERY_MODE PRE_TEST TEST_FILTER "${filter}"
      PROPERTIES ${ARGN} COST ${cost})
    list(APPEND long "${filter}")
  endforeach()
  if(long)
    list(JOIN long ":" negative)
    gtest_discover_tests(test_${layer} DISCOVERY_MODE PRE_TEST TEST_FILTER "-${negative}" PROPERTIES ${ARGN})
  else()
    gtest_discover_tests(test_${layer} DISCOVERY_MODE PRE_TEST PROPERTIES ${ARGN})
  endif()
endfunction()
