#include <polyplan/geometry/rational.hpp>

#include <gtest/gtest.h>

using polyplan::parse_rational;
using polyplan::Rational;

TEST(ParseRational, DecimalsAreExact) {
  // The classic: in binary floating point 0.1 + 0.2 != 0.3. Read from text, it is.
  EXPECT_EQ(*parse_rational("0.1") + *parse_rational("0.2"), *parse_rational("0.3"));
  EXPECT_EQ(*parse_rational("0.1"), Rational(1, 10));
  EXPECT_NE(*parse_rational("0.1"), Rational(0.1));  // the double 0.1 is not 1/10
  EXPECT_EQ(*parse_rational("-2.50"), Rational(-5, 2));
  EXPECT_EQ(*parse_rational(".5"), Rational(1, 2));
  EXPECT_EQ(*parse_rational("5."), Rational(5));
  EXPECT_EQ(*parse_rational("5.000000001"), Rational(5000000001, 1000000000));
}

TEST(ParseRational, Exponents) {
  EXPECT_EQ(*parse_rational("1e-3"), Rational(1, 1000));
  EXPECT_EQ(*parse_rational("2.5E+2"), Rational(250));
  EXPECT_EQ(*parse_rational("-1.25e1"), Rational(-25, 2));
  EXPECT_EQ(*parse_rational("1e-10") * 10000000000, Rational(1));
}

TEST(ParseRational, Rationals) {
  EXPECT_EQ(*parse_rational("1/3") * 3, Rational(1));
  EXPECT_EQ(*parse_rational("-6/4"), Rational(-3, 2));
  EXPECT_EQ(*parse_rational("12"), Rational(12));
  EXPECT_EQ(polyplan::to_string(*parse_rational("-6/4")), "-3/2");
  EXPECT_EQ(polyplan::to_string(*parse_rational("0.75")), "3/4");
}

TEST(ParseRational, RejectsWithAReason) {
  std::string why;
  EXPECT_FALSE(parse_rational("1/0", &why));
  EXPECT_EQ(why, "zero denominator");
  for (const char* bad : {"abc", "", "1/3/4", "1.2.3", "--1", "1e", "e5", "0x10", "1/-3", "."}) {
    EXPECT_FALSE(parse_rational(bad, &why)) << bad;
    EXPECT_EQ(why, "not a number") << bad;
  }
  EXPECT_FALSE(parse_rational("1e999999999", &why));
  EXPECT_EQ(why, "exponent out of range");
}

TEST(ToDouble, RoundsToNearest) {
  EXPECT_EQ(polyplan::to_double(Rational(21, 5)), 4.2);  // truncation would give 4.199999999999999
  EXPECT_EQ(polyplan::to_double(Rational(1, 10)), 0.1);
  EXPECT_EQ(polyplan::to_double(Rational(-7, 10)), -0.7);
  EXPECT_EQ(polyplan::to_double(*parse_rational("0.30000000000000004")), 0.30000000000000004);
}

TEST(ToString, PointsAreNamedAsMessagesNameThem) {
  EXPECT_EQ(polyplan::to_string(polyplan::ExactPoint{Rational(3, 2), Rational(-7)}), "[3/2, -7]");
  EXPECT_EQ(polyplan::to_string(polyplan::ExactPoint{*parse_rational("0.75"), *parse_rational("-2/6")}), "[3/4, -1/3]");
  EXPECT_EQ(polyplan::to_string(polyplan::ExactPoint{Rational(0), *parse_rational("1e3")}), "[0, 1000]");
}
