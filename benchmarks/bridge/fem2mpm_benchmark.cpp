// fem2mpm throughput: particles written per second on the paper's column (50 m x 40 m, 50 x 40 SSPquads,
// 4 x 4 particles per element = 32,000 particles) and on meshes 10x and 100x larger (same column, finer
// elements). The recorder files are synthetic (a geostatic-like stress field and a smooth displacement
// and velocity field, written in OpenSees' format at 6 significant digits). Prints the median over
// repeats of the whole pipeline (fem2mpm --quiet: read, recover, map, report, write HDF5 + deck) and of
// its phases. Target (issue 5): >= 1 million particles per second, linear growth with mesh size.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "bridge/cli.hpp"
#include "bridge/fem_model.hpp"
#include "bridge/fem_state_reader.hpp"
#include "bridge/mpm_deck.hpp"
#include "bridge/particle_mapping.hpp"
#include "bridge/stress_recovery.hpp"
#include "mpm/io/particle_table.hpp"

namespace fs = std::filesystem;

namespace {

struct Case {
  const char* name;
  int nx, ny;
};

/// Writes model.json, disp.out, vel.out, stress.out for an nx x ny SSPquad column of 50 m x 40 m (kN units).
void write_case(const fs::path& dir, int nx, int ny) {
  fs::create_directories(dir);
  const double w = 50, h = 40, dx = w / nx, dy = h / ny;
  {
    std::ofstream f(dir / "model.json");
    f << "{\n\"StructuralAnalysisModel\": {\n\t\"properties\": {\n\t\t\"ndMaterials\": [\n"
      << "\t\t\t{\"name\": \"1\", \"type\": \"MohrCoulomb\", \"E\": 172000, \"nu\": 0.23, \"rho\": 1.925, \"phi\": 22.2, "
         "\"c\": 0.1, \"psi\": 0, \"tension\": null}\n\t\t]\n\t},\n\t\"geometry\": {\n\t\t\"nodes\": [\n";
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i)
        f << "\t\t\t{\"name\": " << j * (nx + 1) + i + 1 << ", \"ndf\": 2, \"crd\": [" << i * dx << ", " << j * dy << "]}"
          << (j == ny && i == nx ? "\n" : ",\n");
    f << "\t\t],\n\t\t\"elements\": [\n";
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const int n1 = j * (nx + 1) + i + 1;
        f << "\t\t\t{\"name\": " << j * nx + i + 1 << ", \"type\": \"SSPquad\", \"nodes\": [" << n1 << ", " << n1 + 1 << ", "
          << n1 + nx + 2 << ", " << n1 + nx + 1 << "], \"thickness\": 1, \"bodyForces\": [0, -18.8843], \"material\": \"1\"}"
          << (j == ny - 1 && i == nx - 1 ? "\n" : ",\n");
      }
    f << "\t\t]\n\t}\n}\n}\n";
  }
  std::ofstream disp(dir / "disp.out"), vel(dir / "vel.out"), stress(dir / "stress.out");
  disp.precision(6);
  vel.precision(6);
  stress.precision(6);
  for (double t : {0.5, 1.0}) {
    disp << t;
    vel << t;
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) {
        const double x = i * dx, y = j * dy;
        disp << ' ' << t * 0.01 * x * y / (w * h) << ' ' << -t * 0.02 * y / h;
        vel << ' ' << 0.1 * x * y / (w * h) << ' ' << -0.05 * y / h;
      }
    disp << '\n';
    vel << '\n';
    stress << t;
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const double yc = (j + 0.5) * dy, xc = (i + 0.5) * dx;
        const double syy = -18.8843 * (h - yc);
        stress << ' ' << 0.3 * syy << ' ' << syy << ' ' << 0.01 * syy * xc / w;
      }
    stress << '\n';
  }
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

template <class F>
double seconds(F&& f) {
  const auto t0 = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

int main(int argc, char** argv) {
  const int repeats = argc > 1 ? std::max(1, std::atoi(argv[1])) : 5;
  const fs::path root = fs::temp_directory_path() / ("fem2mpm_benchmark_" + std::to_string(::getpid()));
  const Case cases[] = {{"paper column (50 x 40)", 50, 40}, {"10x (158 x 126)", 158, 126}, {"100x (500 x 400)", 500, 400}};
  std::printf("fem2mpm benchmark: median of %d repeats, SSPquad column, 4x4 particles per element, IDW recovery\n", repeats);
  std::printf("%-24s %10s %10s | %9s %9s %9s %9s %9s | %12s\n", "mesh", "elements", "particles", "read s", "map s",
              "h5 s", "deck s", "total s", "particles/s");
  for (const Case& c : cases) {
    const fs::path dir = root / c.name;
    write_case(dir, c.nx, c.ny);
    const std::string out = (dir / "deck").string();
    const std::string model = (dir / "model.json").string(), disp = (dir / "disp.out").string(),
                      vel = (dir / "vel.out").string(), stress = (dir / "stress.out").string();
    std::vector<double> t_read, t_map, t_h5, t_deck, t_total;
    std::size_t count = 0;
    for (int r = 0; r < repeats; ++r) {
      // Phases through the library.
      bridge::ReadOptions ro;
      ro.disp = disp;
      ro.vel = vel;
      ro.stress = stress;
      ro.units = bridge::Units::kN;
      ro.time = 1.0;
      bridge::AssembledState a;
      t_read.push_back(seconds([&] { a = bridge::read_fem_state(bridge::read_fem_model(model), ro); }));
      bridge::ParticleList particles;
      t_map.push_back(seconds([&] {
        particles = bridge::generate_particles(a.state, bridge::recover_nodal_stress(a.state, bridge::Recovery::InverseDistance), {});
      }));
      count = particles.size();
      fs::remove_all(dir / "phase");
      fs::create_directories(dir / "phase");
      t_h5.push_back(seconds([&] { mpm::io::write_particle_table(dir / "phase/particles.h5", particles); }));
      t_deck.push_back(seconds([&] {
        const auto d = bridge::build_deck(a.state, particles, {});
        std::ofstream(dir / "phase/mesh.txt") << d.mesh_txt;
        for (const auto& [name, body] : d.particle_files) std::ofstream(dir / "phase" / name) << body;
      }));
      // The whole program.
      const char* args[] = {"fem2mpm", "--model", model.c_str(), "--disp", disp.c_str(), "--vel", vel.c_str(), "--stress",
                            stress.c_str(), "--units", "kN", "--time", "1", "--out", out.c_str(), "--quiet"};
      int rc = 0;
      fs::remove_all(dir / "deck");  // a fresh output folder, as a user's first run (deleting is not timed)
      fs::remove_all(dir / "phase");
      t_total.push_back(seconds([&] { rc = bridge::run_cli(16, args, std::cout, std::cerr); }));
      if (rc != 0) return 1;
    }
    const double total = median(t_total);
    std::printf("%-24s %10zu %10zu | %9.4f %9.4f %9.4f %9.4f %9.4f | %12.3e\n", c.name,
                static_cast<std::size_t>(c.nx) * c.ny, count, median(t_read), median(t_map), median(t_h5), median(t_deck),
                total, static_cast<double>(count) / total);
  }
  if (std::getenv("FEM2MPM_BENCHMARK_KEEP")) std::printf("inputs kept in %s\n", root.c_str());
  else fs::remove_all(root);
  return 0;
}
