// The accuracy comparison's scoring and tuning sweep.
#include <limits>
#include <set>

#include <gtest/gtest.h>

#include "accuracy_comparison.hpp"
#include "comparison_filters.hpp"
#include "scanfilter/removal_score.hpp"
#include "scanfilter/sim/labelled_log.hpp"

namespace scanfilter::cli {
namespace {

constexpr auto code(PointCode c) { return static_cast<std::uint8_t>(c); }

TEST(RemovalScore, FalseDeletionsByRangeBandAndClassAgnosticPrecision) {
  Scan scan;
  scan.ranges = {1.0, 3.0, 5.0, 2.0, 2.0, std::numeric_limits<double>::quiet_NaN()};
  scan.truth = {code(PointCode::kValid), code(PointCode::kValid), code(PointCode::kValid),
                code(PointCode::kJump),  code(PointCode::kMisdetected), code(PointCode::kNoReturn)};
  // A baseline that says "jump" for everything it removes.
  const std::vector<std::uint8_t> labels = {code(PointCode::kJump), code(PointCode::kValid), code(PointCode::kJump),
                                            code(PointCode::kJump), code(PointCode::kValid), code(PointCode::kNoReturn)};
  RemovalScore s;
  s.add(scan, labels);
  EXPECT_DOUBLE_EQ(s.falseDeletionRate(0), 1.0);  // the 1 m point
  EXPECT_DOUBLE_EQ(s.falseDeletionRate(1), 0.0);  // the 3 m point
  EXPECT_DOUBLE_EQ(s.falseDeletionRate(2), 1.0);  // the 5 m point
  EXPECT_DOUBLE_EQ(s.falseDeletionRate(), 2.0 / 3.0);
  EXPECT_DOUBLE_EQ(s.removalPrecision(s.jump()), 1.0 / 3.0);  // 1 jump point against 2 valid points removed
  EXPECT_DOUBLE_EQ(s.removalPrecision(s.misdetected()), 0.0);
  EXPECT_DOUBLE_EQ(s.artefactRecall(), 0.5);
  EXPECT_DOUBLE_EQ(s.artefactPrecision(), 1.0 / 3.0);
  RemovalScore merged;
  merged.add(s);
  merged.add(s);
  EXPECT_DOUBLE_EQ(merged.falseDeletionRate(2), 1.0);
}

TEST(SweepPoints, DefaultsFirstThenTheRestOfTheGridWithinTheBudget) {
  for (const auto& family : comparisonFamilies(FilterConfig{})) {
    std::size_t grid = 1;
    for (const auto& axis : family.axes) grid *= axis.values.size();
    const auto all = sweepPoints(family, grid + 10);
    ASSERT_EQ(all.size(), grid) << family.name;
    for (const auto& axis : family.axes) EXPECT_EQ(all.front().at(axis.name), axis.values.front()) << family.name;
    EXPECT_EQ(std::set<ParamValues>(all.begin(), all.end()).size(), grid) << family.name << ": repeated points";
    const auto five = sweepPoints(family, 5);
    ASSERT_EQ(five.size(), std::min<std::size_t>(5, grid));
    EXPECT_EQ(five, sweepPoints(family, 5)) << "deterministic";
    EXPECT_EQ(std::vector<ParamValues>(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(five.size())), five)
        << "a bigger budget extends a smaller one";
  }
}

TEST(TuneFamily, SpendsTheBudgetAndNeverEndsBelowTheDefaults) {
  const auto log = sim::simulateLog(sim::findScene("office"), 1, "office", 40);
  const std::vector<sim::LabelledLog> logs{log};
  for (const auto& family : comparisonFamilies(FilterConfig{})) {
    const TunedFamily tuned = tuneFamily(family, logs, 4);
    EXPECT_EQ(tuned.evaluations, 4u) << family.name;
    const double at_default = scoreFamily(family, tuned.defaults, logs).score.artefactF1();
    EXPECT_GE(tuned.tuned_objective, at_default) << family.name;
    EXPECT_DOUBLE_EQ(scoreFamily(family, tuned.tuned, logs).score.artefactF1(), tuned.tuned_objective)
        << family.name << ": scoring is repeatable";
  }
}

}  // namespace
}  // namespace scanfilter::cli
