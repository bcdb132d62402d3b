#pragma once
// Helpers of the mpm regression tests: scratch copies of the CB-Geo reference decks, running the
// mpm binary, unpacking the gzipped reference HDF5 files, and the statistics summarize.py computes.
#include <gtest/gtest.h>
#include <zlib.h>

#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "mpm/io/particle_table.hpp"
#include "mpm/io/results.hpp"
#include "support/scratch.hpp"

namespace mpm_regression {

namespace fs = std::filesystem;

inline const fs::path kCases = fs::path(GEOFLOW_TEST_DATA_DIR) / "reference_runs/cbgeo";
inline const fs::path kMpm = fs::path(GEOFLOW_BIN_DIR) / "mpm";

inline fs::path scratch_root() { return test_support::scratch_folder("geoflow_mpm_regression"); }

/// Removes this process's scratch folder unless the test failed (then it is kept to look at).
class ScratchCleanup : public ::testing::EmptyTestEventListener {
  void OnTestEnd(const ::testing::TestInfo& info) override {
    if (info.result() && info.result()->Passed()) {
      std::error_code ec;
      fs::remove_all(scratch_root(), ec);
    }
  }
};

/// Registers ScratchCleanup once per test program.
inline const bool kCleanupRegistered = [] {
  ::testing::UnitTest::GetInstance()->listeners().Append(new ScratchCleanup);
  return true;
}();

/// A copy of reference case `name` (without its ref/ folder) in a fresh scratch folder `tag`.
inline fs::path copy_case(const std::string& name, const std::string& tag) {
  const fs::path dst = scratch_root() / tag;
  fs::remove_all(dst);
  fs::create_directories(dst);
  for (const auto& e : fs::directory_iterator(kCases / name))
    if (e.path().filename() != "ref") fs::copy(e.path(), dst / e.path().filename(), fs::copy_options::recursive);
  return dst;
}

struct RunResult {
  int exit_code = -1;
  std::string out, err;
};

/// Runs `mpm -f dir/ -i input args`; stdout and stderr are captured.
inline RunResult run_mpm(const fs::path& dir, const std::string& input = "mpm.json", const std::string& args = "--threads 2") {
  const fs::path out = dir / "stdout.txt", err = dir / "stderr.txt";
  // Passive OpenMP waiting, as the reference runs used: the test machine's 2 cores are shared.
  const std::string cmd = "OMP_WAIT_POLICY=passive '" + kMpm.string() + "' -f '" + dir.string() + "/' -i '" + input + "' " + args + " > '" +
                          out.string() + "' 2> '" + err.string() + "'";
  const int status = std::system(cmd.c_str());
  RunResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  auto slurp = [](const fs::path& f) {
    std::ifstream in(f);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  };
  r.out = slurp(out);
  r.err = slurp(err);
  fs::remove(out);
  fs::remove(err);
  return r;
}

/// Reads a gzipped CB-Geo particle file (ref/particlesNNNN.h5.gz) through a scratch copy.
inline std::vector<mpm::ParticleRecord> read_gz_table(const fs::path& gz) {
  const fs::path plain = scratch_root() / ("unpacked_" + gz.stem().string());
  fs::create_directories(scratch_root());
  gzFile in = gzopen(gz.c_str(), "rb");
  if (!in) throw std::runtime_error(gz.string() + ": cannot open");
  std::ofstream out(plain, std::ios::binary);
  std::vector<char> buffer(1 << 16);
  int n = 0;
  while ((n = gzread(in, buffer.data(), static_cast<unsigned>(buffer.size()))) > 0) out.write(buffer.data(), n);
  gzclose(in);
  out.close();
  auto records = mpm::io::read_particle_table(plain);
  fs::remove(plain);
  return records;
}

/// The per-file statistics of cbgeo/tools/summarize.py (mass-weighted means, numpy percentiles).
struct Stats {
  std::size_t n = 0;
  double mass = 0, cx = 0, cy = 0, vx = 0, vy = 0, ke = 0, min_syy = 0, max_syy = 0, p98x = 0, p995y = 0, vmax = 0;
};

inline Stats stats_of(const std::vector<mpm::ParticleRecord>& ps) {
  Stats s;
  s.n = ps.size();
  std::vector<double> xs, ys;
  s.min_syy = 1e300;
  s.max_syy = -1e300;
  for (const auto& p : ps) {
    s.mass += p.mass;
    s.cx += p.mass * p.coord_x;
    s.cy += p.mass * p.coord_y;
    s.vx += p.mass * p.velocity_x;
    s.vy += p.mass * p.velocity_y;
    const double v2 = p.velocity_x * p.velocity_x + p.velocity_y * p.velocity_y;
    s.ke += 0.5 * p.mass * v2;
    s.vmax = std::max(s.vmax, std::sqrt(v2));
    s.min_syy = std::min(s.min_syy, p.stress_yy);
    s.max_syy = std::max(s.max_syy, p.stress_yy);
    xs.push_back(p.coord_x);
    ys.push_back(p.coord_y);
  }
  s.cx /= s.mass;
  s.cy /= s.mass;
  s.vx /= s.mass;
  s.vy /= s.mass;
  s.p98x = mpm::io::percentile(xs, 98);
  s.p995y = mpm::io::percentile(ys, 99.5);
  return s;
}

/// A CSV file with a header row: column name -> values.
inline std::map<std::string, std::vector<double>> read_csv(const fs::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error(file.string() + ": cannot open");
  std::string line;
  std::getline(in, line);
  std::vector<std::string> names;
  {
    std::stringstream h(line);
    for (std::string w; std::getline(h, w, ',');) names.push_back(w);
  }
  std::map<std::string, std::vector<double>> cols;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    std::stringstream r(line);
    std::string w;
    for (std::size_t c = 0; c < names.size() && std::getline(r, w, ','); ++c) cols[names[c]].push_back(std::stod(w));
  }
  return cols;
}

inline std::string file_text(const fs::path& f) {
  std::ifstream in(f);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace mpm_regression
