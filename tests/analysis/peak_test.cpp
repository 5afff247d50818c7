// Peaks of a curve and the peak rule (analysis/peak.h) on analytic curves.
#include "analysis/peak.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

using namespace grainlab::analysis;

namespace {
const double kNan = std::numeric_limits<double>::quiet_NaN();

// e_k = k / (n - 1) over [0, 1], and y = f(e) on it.
template <class F>
void sample(int n, F f, std::vector<double>& e, std::vector<double>& y) {
  for (int k = 0; k < n; ++k) e.push_back(double(k) / (n - 1)), y.push_back(f(e.back()));
}
}  // namespace

TEST(SeriesPeak, LargestFiniteValue) {
  EXPECT_EQ(series_peak(std::vector<double>{kNan, 0.1, 0.3, kNan, 0.2}), 0.3);
  EXPECT_EQ(series_peak(std::vector<double>{-2.0, -1.0}), -1.0);
  EXPECT_FALSE(series_peak(std::vector<double>{kNan, kNan}).has_value());
  EXPECT_FALSE(series_peak({}).has_value());
}

TEST(PeakRule, TheLastFivePercentOfTheTestIsNoPeak) {
  EXPECT_TRUE(is_peak_at(0.5, 1.0));
  EXPECT_TRUE(is_peak_at(0.9499, 1.0));
  EXPECT_FALSE(is_peak_at(0.95, 1.0));
  EXPECT_FALSE(is_peak_at(1.0, 1.0));
  EXPECT_FALSE(is_peak_at(0.019, 0.02));  // 0.95 x 0.02 = 0.019
}

TEST(CurvePeak, AKnownPeakIsFoundWhereItIs) {
  // y = e exp(-e / 0.3): the largest value 0.3/e at e = 0.3, well before the end.
  std::vector<double> e, y;
  sample(101, [](double x) { return x * std::exp(-x / 0.3); }, e, y);
  const auto p = curve_peak(y, e);
  ASSERT_TRUE(p.has_value());
  EXPECT_EQ(p->index, 30u);
  EXPECT_DOUBLE_EQ(p->at, 0.3);
  EXPECT_NEAR(p->value, 0.3 / std::exp(1.0), 1e-15);
  EXPECT_TRUE(p->is_peak);
}

TEST(CurvePeak, ACurveRisingToTheEndHasNoPeak) {
  // y = 1 - exp(-3 e): rising everywhere, largest at the last sample.
  std::vector<double> e, y;
  sample(41, [](double x) { return 1 - std::exp(-3 * x); }, e, y);
  const auto p = curve_peak(y, e);
  ASSERT_TRUE(p.has_value());
  EXPECT_EQ(p->index, 40u);
  EXPECT_DOUBLE_EQ(p->at, 1.0);
  EXPECT_FALSE(p->is_peak);
  // A flat top from e = 0.96 on is no peak either; from e = 0.5 on it is (the first largest sample counts).
  std::vector<double> top = e;
  for (double& v : top) v = std::min(v, 0.96);
  EXPECT_FALSE(curve_peak(top, e)->is_peak);
  for (double& v : top) v = std::min(v, 0.5);
  EXPECT_TRUE(curve_peak(top, e)->is_peak);
  EXPECT_DOUBLE_EQ(curve_peak(top, e)->at, 0.5);
}

TEST(CurvePeak, NanSamplesAreSkippedAndTheEndIsTheLargestProgress) {
  // The largest value at e = 0.9, and the last samples' progress NaN: the end is still e = 1.
  const std::vector<double> e = {0.0, 0.5, 0.9, 1.0, kNan}, y = {kNan, 1.0, 2.0, 1.5, 9.0};
  const auto p = curve_peak(y, e);
  ASSERT_TRUE(p.has_value());
  EXPECT_EQ(p->index, 2u);
  EXPECT_TRUE(p->is_peak);
  EXPECT_FALSE(curve_peak(std::vector<double>{kNan, kNan}, std::vector<double>{0.0, 1.0}).has_value());
  EXPECT_FALSE(curve_peak({}, {}).has_value());
}
