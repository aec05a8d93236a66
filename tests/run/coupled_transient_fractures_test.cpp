// The counts of a coupled transient run's fractures (run/coupled_transient_fractures.hpp): what
// history.csv's open_fractures … largest_hydraulic_aperture columns hold and what
// figures/fractures.* draws, from fracture results of known values. Sums and maxima: exact.

#include <gtest/gtest.h>

#include <stdexcept>

#include "run/coupled_transient_fractures.hpp"

namespace hydrodda::run {
namespace {

fractures::FractureResult fracture(double open_length, bool open, double max_aperture, double hydraulic) {
  fractures::FractureResult f;
  f.open_length = open_length;
  f.open = open;
  f.max_aperture = max_aperture;
  f.hydraulic_aperture = hydraulic;
  return f;
}

TEST(CoupledTransientFractures, CountsTheOpenAndPartlyOpenFracturesAndSumsTheirOpenLength) {
  fractures::FractureState state;
  state.fractures = {fracture(0.0, false, 0.0, 3e-6), fracture(2.5, false, 4e-5, 2e-5),
                     fracture(9.5, true, 1e-4, 9e-5), fracture(0.0, false, 0.0, 1.2e-4)};
  const FractureCounts c = count_fractures(state);
  EXPECT_EQ(c.open, 1);
  EXPECT_EQ(c.partly_open, 2);
  EXPECT_EQ(c.open_length, 12.0);
  EXPECT_EQ(c.largest_opening, 1e-4);
  EXPECT_EQ(c.largest_hydraulic, 1.2e-4);  // a closed joint may conduct most
  EXPECT_EQ(fracture_count_cells(c).size(), fracture_count_columns().size());
}

TEST(CoupledTransientFractures, NoFractureCountsNothing) {
  const FractureCounts c = count_fractures({});
  EXPECT_EQ(c.open, 0);
  EXPECT_EQ(c.partly_open, 0);
  EXPECT_EQ(c.open_length, 0.0);
  EXPECT_EQ(c.largest_opening, 0.0);
}

TEST(CoupledTransientFractures, TheFigureDrawsTheOpenLengthAtEachTime) {
  FractureCounts a, b;
  b.open_length = 3.0;
  const output::LinePlotSpec plot = plot_open_fractures({0.0, 10.0}, {a, b});
  ASSERT_EQ(plot.series.size(), 1u);
  EXPECT_EQ(plot.series[0].x, (std::vector<double>{0.0, 10.0}));
  EXPECT_EQ(plot.series[0].y, (std::vector<double>{0.0, 3.0}));
  EXPECT_EQ(plot.x_label, "time (s)");
  EXPECT_THROW(plot_open_fractures({0.0}, {a, b}), std::invalid_argument);
}

}  // namespace
}  // namespace hydrodda::run
