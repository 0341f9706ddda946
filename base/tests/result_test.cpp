#include "base/result.hpp"

#include <gtest/gtest.h>

#include <cerrno>
#include <string>
#include <variant>

namespace l2 {
namespace {

Result<int> parse_digit(char c) {
  if (c < '0' || c > '9') return Failure{std::string("not a digit: ") + c};
  return c - '0';
}

Status check_even(int n) {
  if (n % 2 != 0) return Failure{"odd: " + std::to_string(n), EDOM};
  return {};
}

TEST(Result, HoldsTheValueOrTheReason) {
  const Result<int> seven = parse_digit('7');
  ASSERT_TRUE(seven.ok());
  EXPECT_EQ(*seven, 7);
  EXPECT_EQ(seven.reason(), "");
  const Result<int> letter = parse_digit('x');
  ASSERT_FALSE(letter.ok());
  EXPECT_EQ(letter.reason(), "not a digit: x");
  EXPECT_THROW((void)letter.value(), std::bad_variant_access);
}

TEST(Status, OkOrAReasonWithItsErrno) {
  EXPECT_TRUE(check_even(4).ok());
  const Status odd = check_even(3);
  ASSERT_FALSE(odd.ok());
  EXPECT_EQ(odd.reason(), "odd: 3");
  EXPECT_EQ(odd.error(), EDOM);
  EXPECT_EQ(Result<int>(Failure{"x", EDOM}).error(), EDOM);
}

}  // namespace
}  // namespace l2
