// mpm: the explicit MPM engine with CB-Geo's command line and input deck.
//   mpm -f <working_dir>/ -i mpm.json [--threads N]
// Exit status: 0 done; 2 bad input (nothing written); 3 numerical failure (the last good state is
// written, resumable); 1 any other failure (e.g. a file that cannot be written).
#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>
#include <string>

#include "common/input_error.hpp"
#include "common/number_text.hpp"
#include "common/printable_text.hpp"
#include "mpm/core/energy_audit.hpp"
#include "mpm/core/simulation.hpp"
#include "mpm/io/deck_reader.hpp"
#include "mpm/io/particle_table.hpp"
#include "mpm/io/progress.hpp"
#include "mpm/io/results.hpp"

namespace {

int run(const std::string& working_dir, const std::string& input_file, int threads) {
  const mpm::Deck deck = mpm::io::read_deck(working_dir, input_file);
  for (const auto& w : deck.warnings) std::fprintf(stderr, "mpm: warning: %s\n", w.c_str());
  mpm::core::Simulation sim(deck, threads);
  mpm::io::ResultsWriter results(deck);
  mpm::io::ProgressLine progress(deck.first_step, deck.analysis.nsteps);
  const long long nsteps = deck.analysis.nsteps, every = deck.output.output_steps;
  // Warnings during the run end the progress line first. With analysis.locate_particles false, particles
  // that leave the grid are removed (CB-Geo's rule): said when it first happens and counted at the end.
  const auto say = [&](const std::string& warning) {
    if (warning.empty()) return;
    progress.finish();
    std::fprintf(stderr, "mpm: warning: %s\n", warning.c_str());
  };
  const std::size_t particles_at_start = sim.particle_count();
  bool removal_said = false;
  const auto removed = [&](const std::string& first_or_all) {
    return first_or_all + std::to_string(particles_at_start - sim.particle_count()) + " of " +
           std::to_string(particles_at_start) + " particles left the grid and were removed by t = " +
           common::number_text(sim.time(), 6) + " s (analysis.locate_particles is false)";
  };
  if (sim.courant_number() > 1.0)
    say("analysis.dt = " + common::number_text(sim.dt(), 6) + " s is above the elastic limit h / c_p = " +
        common::number_text(sim.dt() / sim.courant_number(), 6) + " s (Courant number " +
        common::number_text(sim.courant_number(), 3) + "): the explicit step is unstable there; use analysis.cfl (0.5 "
        "or less) or a smaller dt");
  mpm::core::EnergyAudit energy(deck);
  try {
    const auto start = sim.snapshot();
    results.write_start(sim.time(), start);
    energy.check(sim.time(), start);
    while (sim.step_index() < nsteps) {
      const long long step = sim.step_index();
      sim.step();
      if (step % every == 0) {
        const auto state = sim.snapshot();
        results.write_output(step, sim.time(), sim.dt(), state,
                             deck.output.writes_particles(step) ? sim.file_extras() : mpm::ParticleFileExtras{});
        say(energy.check(sim.time(), state));
      }
      if (!removal_said && sim.particle_count() < particles_at_start) {
        say(removed(""));
        removal_said = true;
      }
      progress.update(step, sim.time(), sim.dt(), sim.particle_count());
    }
  } catch (const common::NumericalError& e) {
    progress.finish();
    // The engine keeps the state of the last completed step (loop step step_index() - 1).
    const long long last = sim.step_index() - 1;
    std::string saved = "no step completed (only the initial outputs are written)";
    if (last >= deck.first_step) saved = "last good state (step " + std::to_string(last) + ") written to " +
                                         results.write_state(last, sim.time(), sim.snapshot(), sim.file_extras()).string();
    std::fprintf(stderr, "mpm: %s; %s\n", common::printable(e.what()).c_str(), saved.c_str());
    return 3;
  }
  progress.finish();
  if (removal_said) say(removed("in all, "));
  if (sim.step_index() > deck.first_step && (sim.step_index() - 1) % every != 0)
    results.write_series_row(sim.step_index() - 1, sim.time(), sim.dt(), sim.snapshot());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  mpm::io::skip_hdf5_exit_cleanup();
  CLI::App app{"mpm: explicit material point method (CB-Geo MPM input decks and particle files)"};
  std::string working_dir, input_file = "mpm.json";
  int threads = 0;
  app.add_option("-f,--working_dir", working_dir, "working folder holding the deck (CB-Geo: must end with /)")->required();
  app.add_option("-i,--input_file", input_file, "input JSON file in the working folder")->capture_default_str();
  app.add_option("-p,--threads,--parallel", threads, "threads (0: OpenMP's default)")->check(CLI::NonNegativeNumber);
  app.set_version_flag("-v,--version", std::string("mpm (geoflow) ") + GEOFLOW_VERSION);
  app.footer("Exit status: 0 done; 2 bad input (one line naming the file and key; nothing written); 1 an output "
             "could not be written (disk full, permissions); 3 numerical failure (the last good state is written, "
             "resumable). SIGTERM/SIGINT remove the temporary *.tmp.<pid> files of outputs being written.");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }
  try {
    return run(working_dir, input_file, threads);
  } catch (const common::InputError& e) {
    std::fprintf(stderr, "mpm: %s\n", common::printable(e.what()).c_str());
    return 2;
  } catch (const common::NumericalError& e) {
    std::fprintf(stderr, "mpm: %s\n", common::printable(e.what()).c_str());
    return 3;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "mpm: %s\n", common::printable(e.what()).c_str());
    return 1;
  }
}
