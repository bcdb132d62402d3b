// 1D vibrating bar in its first mode (Sulsky, Zhou & Schreyer 1995, CPC 87; Bardenhagen 2002,
// JCP 180); the deck and the exact solution are in tests/support/vibrating_bar.hpp. Checks the period
// and amplitude of the centre-of-mass velocity, and that the error shrinks with refinement.
#include <gtest/gtest.h>

#include <cstdio>

#include "support/vibrating_bar.hpp"

namespace {

using namespace mpm_test;

VibratingBar::Errors run_bar(int cells, mpm::io::Scheme scheme, CellType type) {
  return VibratingBar::run(VibratingBar::deck(cells, scheme, type));
}

TEST(VibratingBar, PeriodAndAmplitudeMatchTheFirstMode) {
  for (auto scheme : {mpm::io::Scheme::USF, mpm::io::Scheme::USL, mpm::io::Scheme::MUSL}) {
    for (auto type : {CellType::Linear4, CellType::Gimp16}) {
      const auto r = run_bar(50, scheme, type);
      SCOPED_TRACE(testing::Message() << "scheme " << static_cast<int>(scheme) << " cell type " << static_cast<int>(type));
      EXPECT_LT(r.period, 0.01);
      EXPECT_LT(r.amplitude, 0.02);
    }
  }
}

TEST(VibratingBar, ErrorShrinksWithRefinement) {
  const auto coarse = run_bar(10, mpm::io::Scheme::MUSL, CellType::Linear4);
  const auto medium = run_bar(20, mpm::io::Scheme::MUSL, CellType::Linear4);
  const auto fine = run_bar(40, mpm::io::Scheme::MUSL, CellType::Linear4);
  std::printf("period error: %.3e (10 cells) %.3e (20) %.3e (40); amplitude error %.3e %.3e %.3e\n",
              coarse.period, medium.period, fine.period, coarse.amplitude, medium.amplitude, fine.amplitude);
  EXPECT_LT(medium.period, coarse.period);
  EXPECT_LT(fine.period, medium.period);
  EXPECT_LT(fine.amplitude, coarse.amplitude);
}

}  // namespace
