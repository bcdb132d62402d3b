#include "mpm/io/progress.hpp"

#include <unistd.h>

namespace mpm::io {

ProgressLine::ProgressLine(long long first_step, long long nsteps, std::FILE* stream)
    : stream_(stream), enabled_(::isatty(::fileno(stream)) != 0), first_(first_step), nsteps_(nsteps),
      start_(std::chrono::steady_clock::now()), last_(start_) {}

void ProgressLine::update(long long step, double time, double dt, std::size_t particles) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  const bool last_step = step + 1 >= nsteps_;
  if (!last_step && now - last_ < std::chrono::milliseconds(200)) return;
  last_ = now;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double done = static_cast<double>(step + 1 - first_), left = static_cast<double>(nsteps_ - step - 1);
  const long eta = done > 0 ? static_cast<long>(elapsed / done * left + 0.5) : 0;
  std::fprintf(stream_, "\rstep %lld/%lld  t %.6g s  dt %.3g s  %zu particles  ETA %ld:%02ld   ", step, nsteps_ - 1,
               time, dt, particles, eta / 60, eta % 60);
  std::fflush(stream_);
  drawn_ = true;
}

void ProgressLine::finish() {
  if (enabled_ && drawn_) {
    std::fputc('\n', stream_);
    std::fflush(stream_);
  }
  drawn_ = false;
}

}  // namespace mpm::io
