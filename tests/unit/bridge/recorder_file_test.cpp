// Unit tests of the recorder reader on OpenSees 3.8 files (reference_runs case 1.1) and damaged copies.
#include <gtest/gtest.h>

#include <fstream>

#include "bridge/recorder_file.hpp"
#include "common/input_error.hpp"
#include "support/input_error_message.hpp"
#include "support/scratch.hpp"
#include "support/tolerance.hpp"

namespace {

const std::filesystem::path kCase =
    std::filesystem::path(GEOFLOW_TEST_DATA_DIR) / "reference_runs/opensees/sspquad_block_surface_load/ref";

using test_support::input_error_message;

std::filesystem::path scratch(const std::string& name, const std::string& text) {
  const auto file = test_support::scratch_folder("bridge_unit") / name;
  std::ofstream(file, std::ios::binary) << text;
  return file;
}

TEST(RecorderFile, IndexesOpenSeesDispFile) {
  const bridge::RecorderFile f(kCase / "disp.out");
  ASSERT_EQ(f.rows().size(), 5u);
  EXPECT_EQ(f.width(), 71u);  // time + 35 nodes x 2
  EXPECT_EQ(f.data_width(), 70u);
  EXPECT_CLOSE(f.rows()[0].time, 0.2, 0, 1e-15);
  EXPECT_CLOSE(f.rows()[4].time, 1.0, 0, 1e-15);
  const auto v = f.values(0);
  ASSERT_EQ(v.size(), 70u);
  // Row 1 of disp.out: node 8 (on the left roller) ux = 0, uy = -5.59539e-07; node 9 ux = -1.07234e-05.
  EXPECT_CLOSE(v[14], 0.0, 0, 0);
  EXPECT_CLOSE(v[15], -5.59539e-07, 0, 1e-15);
  EXPECT_CLOSE(v[16], -1.07234e-05, 0, 1e-15);
  EXPECT_EQ(f.find_time(0.6), 2u);
  EXPECT_EQ(f.find_time(0.6000001), 2u);  // within 6 printed digits
  EXPECT_EQ(f.find_row(-1), 4u);
  EXPECT_EQ(f.find_row(1), 0u);
  EXPECT_EQ(f.where(2), (kCase / "disp.out").string() + ":3");
}

TEST(RecorderFile, TimeNotInFileListsNearestTimes) {
  const bridge::RecorderFile f(kCase / "stress.out");
  const std::string msg = input_error_message([&] { f.find_time(0.7); });
  EXPECT_NE(msg.find("stress.out"), std::string::npos) << msg;
  EXPECT_NE(msg.find("0.6 (line 3)"), std::string::npos) << msg;
  EXPECT_NE(msg.find("0.8 (line 4)"), std::string::npos) << msg;
  EXPECT_FALSE(input_error_message([&] { f.find_row(6); }).empty());
}

TEST(RecorderFile, DuplicateTimesTakeTheLastRow) {
  const auto path = scratch("dup.out", "0.5 1 2\n1 3 4\n0.5 5 6\n");
  const bridge::RecorderFile f(path);
  std::vector<int> lines;
  EXPECT_EQ(f.find_time(0.5, &lines), 2u);
  EXPECT_EQ(lines, (std::vector<int>{1, 3}));
  EXPECT_EQ(f.values(2), (std::vector<double>{5, 6}));
}

TEST(RecorderFile, TimesOfACoarserRecorderMatchAFinerOne) {
  // A -precision 10 file and a default (6 digit) one of the same steps: each finds the other's time.
  const bridge::RecorderFile fine(scratch("fine.out", "0.0123456789 1\n0.0246913578 2\n"));
  const bridge::RecorderFile coarse(scratch("coarse.out", "0.0123457 1\n0.0246914 2\n"));
  EXPECT_EQ(coarse.rows_at_time(fine.rows()[1].time, fine.time_digits(1)), (std::vector<std::size_t>{1}));
  EXPECT_EQ(fine.rows_at_time(coarse.rows()[1].time, coarse.time_digits(1)), (std::vector<std::size_t>{1}));
  EXPECT_EQ(coarse.time_digits(0), 6);
  EXPECT_EQ(fine.time_digits(0), 9);
  EXPECT_FALSE(input_error_message([&] { fine.rows_at_time(coarse.rows()[1].time); }).empty());  // exact query
}

TEST(RecorderFile, TruncatedAndBadFilesNameFileAndLine) {
  std::ifstream in(kCase / "disp.out");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  // The last row cut mid-way (mid-number too): the rows before it stay usable, the cut one is refused.
  const bridge::RecorderFile cut(scratch("cut.out", text.substr(0, text.size() - 203)));
  ASSERT_EQ(cut.rows().size(), 5u);
  EXPECT_FALSE(cut.rows()[4].terminated);
  EXPECT_EQ(cut.values(3).size(), 70u);
  std::string msg = input_error_message([&] { cut.values(4); });
  EXPECT_NE(msg.find("cut.out:5"), std::string::npos) << msg;
  EXPECT_NE(msg.find("cut while it was being written"), std::string::npos) << msg;
  msg = input_error_message([&] { bridge::RecorderFile f(scratch("mid.out", "0.1 1 2\n0.2 1\n0.3 1 2\n")); });
  EXPECT_NE(msg.find("mid.out:2"), std::string::npos) << msg;  // a short row inside the file is an error
  const auto bad = scratch("bad.out", "0.1 1 2\n0.2 1 x\n");
  msg = input_error_message([&] { bridge::RecorderFile f(bad); });
  EXPECT_NE(msg.find("bad.out:2"), std::string::npos) << msg;
  EXPECT_NE(msg.find("'x'"), std::string::npos) << msg;
  msg = input_error_message([&] { bridge::RecorderFile f(scratch("empty.out", "")); });
  EXPECT_NE(msg.find("empty"), std::string::npos) << msg;
  msg = input_error_message([&] { bridge::RecorderFile f("/nonexistent/disp.out"); });
  EXPECT_NE(msg.find("/nonexistent/disp.out"), std::string::npos) << msg;
}

}  // namespace
