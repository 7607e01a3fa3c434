#include "scanfilter/stamp.hpp"

#include <gtest/gtest.h>

namespace scanfilter {
namespace {

TEST(Stamp, ParsesDecimalSecondsExactly) {
  EXPECT_EQ(Stamp::parseDecimal("12")->nanoseconds(), 12'000'000'000);
  EXPECT_EQ(Stamp::parseDecimal("12.3")->nanoseconds(), 12'300'000'000);
  EXPECT_EQ(Stamp::parseDecimal("0.05")->nanoseconds(), 50'000'000);
  EXPECT_EQ(Stamp::parseDecimal("1732000000.200700045")->nanoseconds(), 1'732'000'000'200'700'045);
  EXPECT_EQ(Stamp::parseDecimal("1.7e9")->nanoseconds(), 1'700'000'000'000'000'000);
  EXPECT_EQ(Stamp::parseDecimal("25E-9")->nanoseconds(), 25);
  EXPECT_EQ(Stamp::parseDecimal("-0.5")->nanoseconds(), -500'000'000);
  EXPECT_EQ(Stamp::parseDecimal("-0")->nanoseconds(), 0);
}

// A double cannot tell these apart (its spacing at 1.7e9 s is about 240 ns).
TEST(Stamp, KeepsWhatADoubleLoses) {
  const auto a = Stamp::parseDecimal("1732000000.200700000");
  const auto b = Stamp::parseDecimal("1732000000.200700001");
  ASSERT_TRUE(a && b);
  EXPECT_EQ(b->nanoseconds() - a->nanoseconds(), 1);
}

TEST(Stamp, RoundsDigitsBelowANanosecond) {
  EXPECT_EQ(Stamp::parseDecimal("12.300000000000001")->toDecimal(), "12.3");
  EXPECT_EQ(Stamp::parseDecimal("0.0000000005")->nanoseconds(), 1);
  EXPECT_EQ(Stamp::parseDecimal("0.0000000004999")->nanoseconds(), 0);
  EXPECT_EQ(Stamp::parseDecimal("1e-30")->nanoseconds(), 0);
}

TEST(Stamp, RejectsWhatIsNotADecimalNumber) {
  for (const char* bad : {"", "-", ".", "1.2.3", "1e", "1e+", "abc", "12 ", "0x10", "inf", "NaN"})
    EXPECT_FALSE(Stamp::parseDecimal(bad)) << '"' << bad << '"';
  EXPECT_FALSE(Stamp::parseDecimal("1e40")) << "beyond int64 nanoseconds";
  EXPECT_FALSE(Stamp::parseDecimal("99999999999999999999"));
}

TEST(Stamp, FormatsTheShortestExactDecimal) {
  EXPECT_EQ(Stamp::fromNanoseconds(12'300'000'000).toDecimal(), "12.3");
  EXPECT_EQ(Stamp::fromNanoseconds(7'000'000'000).toDecimal(), "7");
  EXPECT_EQ(Stamp::fromNanoseconds(1).toDecimal(), "0.000000001");
  EXPECT_EQ(Stamp::fromNanoseconds(-500'000'000).toDecimal(), "-0.5");
  EXPECT_EQ(Stamp::fromNanoseconds(0).toDecimal(), "0");
  for (const char* text : {"1732000000.200700001", "0.1", "123.456789", "-3.000000007"})
    EXPECT_EQ(Stamp::parseDecimal(text)->toDecimal(), text);
}

TEST(Stamp, SplitsIntoRosSecondsAndNanoseconds) {
  const Stamp s = Stamp::fromSecNanosec(1'732'000'000, 200'700'045);
  EXPECT_EQ(s.sec(), 1'732'000'000);
  EXPECT_EQ(s.nanosec(), 200'700'045u);
  const Stamp negative = Stamp::fromNanoseconds(-1);  // ROS: sec -1, nanosec 999999999
  EXPECT_EQ(negative.sec(), -1);
  EXPECT_EQ(negative.nanosec(), 999'999'999u);
  EXPECT_EQ(Stamp::fromSecNanosec(negative.sec(), negative.nanosec()), negative);
}

TEST(Stamp, MeasuresDurations) {
  const Stamp a = Stamp::fromSecNanosec(1'732'000'000, 0);
  const Stamp b = Stamp::fromSecNanosec(1'732'000'000, 250'000'000);
  EXPECT_DOUBLE_EQ(b.secondsSince(a), 0.25);
  EXPECT_LT(a, b);
}

}  // namespace
}  // namespace scanfilter
