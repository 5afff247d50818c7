// Fitting SH to meshes: a mesh of a grain of known coefficients gives them
// back within the fit's own error; a mesh that is not star-shaped about its
// centroid is refused with a direction.
#include "grains/sh_fit.h"

#include "geometry/mesh_io.h"
#include "geometry/primitives.h"
#include "geometry/test_helpers.h"
#include "grains/sh_grain.h"
#include "grains/sh_test_shapes.h"

#include <gtest/gtest.h>

#include <cmath>

namespace grainlab {
namespace {

TEST(ShFit, RecoversTheCoefficientsOfAGrainMeshedFromThem) {
  // Symmetric about the origin (even degrees), so the centroid, which the fit is about, is the origin.
  const ShCoefficients c = test::lumpy_grain(10, 11, true);
  const TriMesh mesh = sh_mesh(c, 20000, "lumpy");
  const ShFit fit = fit_sh(mesh, 10, "lumpy");
  EXPECT_LT(fit.centre.norm(), 1e-3);
  EXPECT_EQ(fit.directions, 21 * 41);
  // The residual is the mesh's facets: 5e-5 of d_eq at 20,000 faces.
  EXPECT_LT(fit.rms_error / fit.equivalent_diameter, 2e-4);
  EXPECT_GT(fit.rms_error, 0);
  EXPECT_LE(fit.rms_error, fit.max_error);
  double worst = 0;
  for (std::size_t i = 0; i < c.a.size(); ++i) worst = std::max(worst, std::abs(fit.coefficients.a[i] - c.a[i]));
  // Each a_nm is the integral of r conj(Y_nm), |Y_nm| <= 1 in the RMS sense: an
  // RMS error e moves it by at most sqrt(4 pi) e; the centroid's offset adds its own.
  EXPECT_LT(worst, std::sqrt(4 * 3.14159265) * (fit.rms_error + fit.centre.norm()));
  EXPECT_LT(worst, 5e-5 * std::abs(c.at(0, 0)));  // 0.9e-5 measured
  // The largest of the known coefficients beyond a_00 is recovered clearly.
  EXPECT_NEAR(std::abs(fit.coefficients.at(2, 1)), std::abs(c.at(2, 1)), 2e-4);  // of 0.058
}

TEST(ShFit, AFileWrittenFromAFitReadsBack) {
  test::TempDir dir;
  const TriMesh mesh = sh_mesh(test::lumpy_grain(6), 4000, "lumpy");
  const ShFit fit = fit_sh(mesh, 6, "lumpy");
  write_sh_file(fit.coefficients, dir / "fit.dat");
  const ShCoefficients back = read_sh_file(dir / "fit.dat");
  ASSERT_EQ(back.degree, 6);
  for (std::size_t i = 0; i < back.a.size(); ++i) EXPECT_NEAR(std::abs(back.a[i] - fit.coefficients.a[i]), 0, 1e-10);
}

TEST(ShFit, AMeshThatIsNotStarShapedIsRefusedWithADirection) {
  // A U whose base is thick enough to hold the centroid: rays towards the
  // arms' tips leave the base, cross the gap and enter an arm.
  const TriMesh u = prism_mesh({{0, 0}, {3, 0}, {3, 3}, {2, 3}, {2, 2}, {1, 2}, {1, 3}, {0, 3}}, 1.0);
  const std::string e = test::input_error_of([&] { fit_sh(u, 8, "u.stl"); });
  EXPECT_CONTAINS(e, "u.stl: not star-shaped about its centroid: the ray towards theta = ");
  EXPECT_CONTAINS(e, "crosses the surface 3 times");
  // A convex body is star-shaped from its centroid: the box fits (badly at degree 8, but it fits).
  EXPECT_NO_THROW(fit_sh(box_mesh(1, 0.7, 0.5), 8, "box"));
}

}  // namespace
}  // namespace grainlab
