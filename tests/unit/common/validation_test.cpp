// The shared validation layer (common/finite_number, printable_text, json_file, atomic_file targets).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>

#include "common/atomic_file.hpp"
#include "common/command_args.hpp"
#include "common/finite_number.hpp"
#include "common/json_file.hpp"
#include "common/printable_text.hpp"
#include "support/input_error_message.hpp"
#include "support/scratch.hpp"

namespace {

using common::NumberRange;
constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(NumberRange, NonFiniteIsNeverAdmissible) {
  for (const auto& r : {NumberRange::any(), NumberRange::positive(), NumberRange::non_negative(), NumberRange::closed(0, 1)}) {
    EXPECT_FALSE(r.contains(kNan));
    EXPECT_FALSE(r.contains(kInf));
    EXPECT_FALSE(r.contains(-kInf));
  }
  EXPECT_TRUE(NumberRange::any().contains(-1e300));
}

TEST(NumberRange, BoundsAndMessages) {
  EXPECT_EQ(common::number_problem(0.5, NumberRange::closed_open(0, 1)), "");
  EXPECT_EQ(common::number_problem(1, NumberRange::closed_open(0, 1)), "expected a number in [0, 1), got 1");
  EXPECT_EQ(common::number_problem(0, NumberRange::positive()), "expected a number > 0, got 0");
  EXPECT_EQ(common::number_problem(-1, NumberRange::non_negative()), "expected a number >= 0, got -1");
  EXPECT_EQ(common::number_problem(kNan), "expected a finite number, got nan");
  EXPECT_EQ(common::number_problem(95, NumberRange::closed_open(0, 90).named("an angle in degrees")),
            "expected an angle in degrees in [0, 90), got 95");
  EXPECT_EQ(test_support::input_error_message([] { common::checked_number(kInf, NumberRange::positive(), "--dt"); }),
            "--dt: expected a number > 0, got inf");
}

TEST(NumberRange, IntegersAndSizes) {
  EXPECT_EQ(common::integer_problem(3, 0, 10), "");
  EXPECT_NE(common::integer_problem(3.5, 0, 10), "");
  EXPECT_NE(common::integer_problem(kNan, 0, 10), "");
  EXPECT_EQ(common::size_problem(1000, 416, "rows"), "");
  EXPECT_NE(common::size_problem(1e12, 416, "rows").find("1e+12 rows"), std::string::npos);
  EXPECT_NE(common::size_problem(kInf, 8, "cells"), "");
}

TEST(PrintableText, EscapesControlAndInvalidBytesKeepsUtf8) {
  EXPECT_EQ(common::printable("plain text"), "plain text");
  EXPECT_EQ(common::printable(std::string("a\x01\x1b[31m\n\xff", 9)), "a\\x01\\x1b[31m\\n\\xff");
  EXPECT_EQ(common::printable("d\xc3\xa9j\xc3\xa0"), "d\xc3\xa9j\xc3\xa0");  // valid UTF-8 stays
  EXPECT_EQ(common::printable(std::string("\xc3", 1)), "\\xc3");           // cut sequence
  EXPECT_EQ(common::printable(std::string("x\0y", 3)), "x\\x00y");
}

TEST(CommandArgs, NumbersMustBeFinite) {
  common::CommandArgs args("setTime", "setTime t", {"nan"});
  EXPECT_EQ(test_support::input_error_message([&] { args.number("time"); }),
            "setTime: expected time (a finite number), got 'nan'; usage: setTime t");
  common::CommandArgs opt("x", "", {"-inf"});
  EXPECT_NE(test_support::input_error_message([&] { opt.optional_number(); }), "");
  EXPECT_FALSE(common::CommandArgs::parse_finite_number("inf"));
  EXPECT_TRUE(common::CommandArgs::parse_number("inf"));  // syntax only
  EXPECT_FALSE(common::CommandArgs::parse_number("1e400"));
  EXPECT_FALSE(common::CommandArgs::parse_number("-1e400"));
  // Underflow is not an error (Tcl reads 1e-310 as a denormal and 1e-400 as 0).
  EXPECT_EQ(common::CommandArgs::parse_number("1e-310"), 1e-310);
  EXPECT_EQ(common::CommandArgs::parse_number("-1e-400"), -0.0);
}

TEST(JsonFile, OverflowNamesTheKeyPath) {
  EXPECT_EQ(test_support::input_error_message([] { common::parse_json_text(R"({"a": {"b": [1, 2, 1e400]}})", "f.json"); }),
            "f.json: a.b[2]: number overflow parsing '1e400' (the value does not fit a double)");
  EXPECT_EQ(test_support::input_error_message([] { common::parse_json_text(R"({"a": 1, "a": 2})", "f.json"); }),
            "f.json: key \"a\" appears twice in one object");
  const std::string control = test_support::input_error_message([] { common::parse_json_text("{\"a\": \x01}", "f.json"); });
  EXPECT_NE(control.find("f.json: invalid JSON"), std::string::npos) << control;
  EXPECT_EQ(control.find('\x01'), std::string::npos) << "raw control byte in: " << control;
  EXPECT_EQ(common::parse_json_text(R"({"x": [0.5, {"y": 2}]})", "f.json")["x"][1]["y"], 2);
}

TEST(AtomicFile, RefusesTargetsThatAreNotRegularFiles) {
  test_support::ScratchDir dir("common_atomic");
  EXPECT_NE(test_support::input_error_message([] { common::check_output_target("/dev/null"); }).find("a character device"),
            std::string::npos);
  EXPECT_NE(test_support::input_error_message([&] { common::AtomicTextFile f(dir.path()); }).find("a directory"),
            std::string::npos);
  EXPECT_EQ(test_support::input_error_message([&] { common::check_output_target(dir.path() / "absent.txt"); }), "");
  const int before = common::registered_temporaries();
  {
    common::AtomicTextFile f(dir.path() / "out.txt");
    EXPECT_EQ(common::registered_temporaries(), before + 1);
    f.stream() << "done\n";
    f.commit();
  }
  EXPECT_EQ(common::registered_temporaries(), before);
  std::ifstream in(dir.path() / "out.txt");
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "done");
}

}  // namespace
