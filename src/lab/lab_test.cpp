// What LabTest gives every test (lab_test.h): the defaults of a test
// without series or reference, and the band binning of a test that imposes
// no displacement.
#include "lab/lab_test.h"

#include <algorithm>

namespace grainlab {

const std::vector<std::vector<double>>& LabTest::series() const {
  static const std::vector<std::vector<double>> none;
  return none;
}

const std::vector<BodyState>& LabTest::reference() const {
  static const std::vector<BodyState> none;
  return none;
}

BandGeometry whole_specimen_band_geometry(const World& world) {
  BandGeometry b;
  double top = 0, diameters = 0;
  const std::size_t n = world.model.bodies.size();
  for (std::size_t i = 0; i < n; ++i) {
    const BodyModel& g = world.model.bodies[i];
    top = std::max(top, world.state.bodies[i].x.z() + g.bounding_radius);
    diameters += 2 * g.radius;  // volume-equivalent
  }
  b.z_max = top;
  b.layer = n > 0 ? diameters / n : 1;
  b.length = 1;  // no imposed strain: any length
  return b;
}

}  // namespace grainlab
