// fem2mpm --ground-motion (bridge/ground_motion.hpp): the record read as OpenSees' Path series with -dt
// reads it (timeSeries Path, PathSeries::getFactor: linear between samples, factor times the value, 0
// past the end without -useLast), cut at the transfer time and written as the deck's base_acceleration
// on a CB-Geo Linear math function in MPM time.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "bridge/ground_motion.hpp"
#include "bridge/mpm_deck.hpp"
#include "common/input_error.hpp"
#include "mpm/io/math_functions.hpp"
#include "support/bridge_states.hpp"
#include "support/scratch.hpp"
#include "support/tolerance.hpp"

namespace {

bridge::GroundMotion record() { return bridge::GroundMotion(1, 0.1, 2.0, {0.0, 1.0, -2.0}); }

TEST(GroundMotion, ReadsAsOpenSeesPathWithDt) {
  const auto m = record();
  EXPECT_EQ(m.at(-1.0), 0.0);
  EXPECT_EQ(m.at(0.0), 0.0);
  EXPECT_CLOSE(m.at(0.05), 1.0, 1e-15, 0);
  EXPECT_CLOSE(m.at(0.1), 2.0, 1e-15, 0);
  EXPECT_CLOSE(m.at(0.15), -1.0, 1e-12, 0);
  EXPECT_CLOSE(m.at(0.2 - 1e-9), -4.0, 1e-6, 0);
  EXPECT_EQ(m.at(0.2), 0.0);  // the last sample's own time is past the end: 0 (no -useLast), as OpenSees
  EXPECT_EQ(m.at(0.2001), 0.0);
}

TEST(GroundMotion, CutAtTheTransferInMpmTime) {
  const auto table = bridge::motion_after(record(), 0.05, 0.001);
  ASSERT_EQ(table.t.size(), 4u);
  const double t[] = {0.001, 0.051, 0.151, 0.151 + 1e-7}, a[] = {1.0, 2.0, -4.0, 0.0};
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_CLOSE(table.t[k], t[k], 1e-12, 0) << k;
    EXPECT_CLOSE(table.a[k], a[k], 1e-12, 0) << k;
  }
  EXPECT_TRUE(bridge::motion_after(record(), 0.2, 0.001).t.empty());  // the record has ended
}

TEST(GroundMotion, TheDeckShakesOnFromTheTransfer) {
  bridge::TransferState st =
      test_support::resting_state({{0, 0}, {10, 0}, {10, 8}, {0, 8}}, {{0, 1, 2, 3}}, 1800, 50e6, 0.3);
  st.time = 0.12;
  bridge::DeckOptions o;
  o.dt = 1e-3;
  o.duration = 1;
  o.ground_motion = bridge::GroundMotion(2, 0.1, 9.81, {0.0, 0.5, -0.25, 0.0});
  const auto d = bridge::build_deck(st, {}, o);
  const auto deck = nlohmann::json::parse(d.mpm_json);
  const auto& base = deck["external_loading_conditions"]["base_acceleration"];
  EXPECT_EQ(base["dir"], 1);  // UniformExcitation dir 2 = y
  EXPECT_EQ(base["acceleration"], 1.0);
  const auto& f = deck["math_functions"][0];
  EXPECT_EQ(f["type"], "Linear");
  EXPECT_EQ(f["id"], base["math_function_id"]);
  // mpm's Linear function at MPM time t reads the record at FEM time t - t0 + 0.12 (t0 = (step + 1) dt).
  mpm::LinearFunction fn{f["xvalues"].get<std::vector<double>>(), f["fxvalues"].get<std::vector<double>>()};
  for (const double t_fem : {0.12, 0.15, 0.2, 0.25, 0.3, 0.31, 1.0}) {
    SCOPED_TRACE(t_fem);
    EXPECT_CLOSE(fn.value(t_fem - 0.12 + 1e-3), o.ground_motion->at(t_fem), 1e-12, 1e-12);
  }
}

TEST(GroundMotionErrors, NameTheFileLineAndOption) {
  test_support::ScratchDir dir("ground_motion_errors");
  const auto file = dir.path() / "record.txt";
  std::ofstream(file) << "0.0 0.1\n0.2 abc\n";
  const auto message = [&](double dt, int dof) {
    try {
      bridge::read_ground_motion(file, dt, 1.0, dof, "--ground-motion");
    } catch (const common::InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(message(0.01, 1).find("record.txt:2: expected a number, got 'abc'"), std::string::npos) << message(0.01, 1);
  EXPECT_NE(message(0.0, 1).find("--ground-motion-dt: expected a time step > 0, got 0"), std::string::npos);
  EXPECT_NE(message(0.01, 3).find("--ground-motion-dir: expected 1 (x) or 2 (y), got 3"), std::string::npos);
  std::ofstream(file) << "\n \n";
  EXPECT_NE(message(0.01, 1).find("has no values"), std::string::npos);
  std::ofstream(file) << "0 1 2 -3.5e-1\n4\n";
  EXPECT_EQ(bridge::read_ground_motion(file, 0.01, 1.0, 1, "--ground-motion").record.values().size(), 5u);
}

}  // namespace
