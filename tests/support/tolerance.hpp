#pragma once
// The one tolerance helper of the test suite: |actual - expected| <= abs_tol + rel_tol * max(|actual|, |expected|).
// Both tolerances are explicit at every call; never a relative tolerance alone against zero.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

namespace test_support {

struct Tolerance {
  double abs;  ///< absolute part, in the quantity's units
  double rel;  ///< relative part, dimensionless
};

inline bool within(double actual, double expected, Tolerance tol) {
  if (!std::isfinite(actual) || !std::isfinite(expected)) return false;
  return std::abs(actual - expected) <= tol.abs + tol.rel * std::max(std::abs(actual), std::abs(expected));
}

inline ::testing::AssertionResult close(double actual, double expected, Tolerance tol) {
  if (within(actual, expected, tol)) return ::testing::AssertionSuccess();
  std::ostringstream os;
  os.precision(17);
  os << "actual " << actual << " vs expected " << expected << " (diff " << std::abs(actual - expected)
     << ", allowed " << tol.abs << " + " << tol.rel << " * max(|a|,|e|))";
  return ::testing::AssertionFailure() << os.str();
}

}  // namespace test_support

/// EXPECT_CLOSE(actual, expected, abs_tol, rel_tol)
#define EXPECT_CLOSE(actual, expected, abs_tol, rel_tol) \
  EXPECT_TRUE(::test_support::close((actual), (expected), ::test_support::Tolerance{(abs_tol), (rel_tol)}))
#define ASSERT_CLOSE(actual, expected, abs_tol, rel_tol) \
  ASSERT_TRUE(::test_support::close((actual), (expected), ::test_support::Tolerance{(abs_tol), (rel_tol)}))
