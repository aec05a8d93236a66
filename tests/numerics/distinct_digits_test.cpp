// A range's ends printed to as many figures as tell them apart (numerics/distinct_digits.hpp).
// Exact: printf's %g text compared.

#include "numerics/distinct_digits.hpp"

#include <gtest/gtest.h>

#include <array>
#include <string>

namespace hydrodda::numerics {
namespace {

using Ends = std::array<std::string, 2>;

TEST(DistinctDigits, EndsThatDifferAtTheGivenFiguresKeepThem) {
  EXPECT_EQ(format_apart(6.047, 6.142, 4), (Ends{"6.047", "6.142"}));
}

TEST(DistinctDigits, EndsThatAgreeThereGetAsManyMoreAsTellThemApart) {
  // A user's seal held unsettled at 1,687.5 m: K_eff/K_m 228,951 to 229,022 (0.031%), which
  // four figures print as 2.29e+05 twice.
  EXPECT_EQ(format_apart(228951.00685663751, 229022.05912426821, 4), (Ends{"2.2895e+05", "2.2902e+05"}));
  EXPECT_EQ(format_apart(0.262906341, 0.263084389, 3), (Ends{"0.2629", "0.2631"}));
}

TEST(DistinctDigits, EqualEndsOrEndsBeyondNineFiguresStopThere) {
  EXPECT_EQ(format_apart(5.0, 5.0, 4), (Ends{"5", "5"}));
  EXPECT_EQ(format_apart(1.0, 1.0 + 1e-12, 3), (Ends{"1", "1"}));
}

}  // namespace
}  // namespace hydrodda::numerics
