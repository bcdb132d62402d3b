#include "common/atomic_file.hpp"

#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <system_error>

#include "common/input_error.hpp"

namespace common {
namespace {

// The registry of live temporaries: a fixed table (no allocation, no lock) that the signal handler
// can read. A slot is 0 free, 1 being filled, 2 holding a path.
constexpr int kSlots = 64;
constexpr std::size_t kPathBytes = 4096;
std::atomic<int> slot_state[kSlots];
char slot_path[kSlots][kPathBytes];

void register_temporary(const std::filesystem::path& p) {
  const std::string& s = p.native();
  if (s.size() >= kPathBytes) return;  // not cleaned on a signal; still removed on every other path
  for (int k = 0; k < kSlots; ++k) {
    int expected = 0;
    if (slot_state[k].compare_exchange_strong(expected, 1)) {
      std::memcpy(slot_path[k], s.c_str(), s.size() + 1);
      slot_state[k].store(2);
      return;
    }
  }
}

void forget_temporary(const std::filesystem::path& p) {
  for (int k = 0; k < kSlots; ++k) {
    int expected = 2;
    if (slot_state[k].load() == 2 && p.native() == slot_path[k] && slot_state[k].compare_exchange_strong(expected, 1))
      slot_state[k].store(0);
  }
}

constexpr int kSignals[] = {SIGTERM, SIGINT, SIGHUP};

extern "C" void remove_temporaries_and_reraise(int sig) {
  for (int k = 0; k < kSlots; ++k)
    if (slot_state[k].load() == 2) ::unlink(slot_path[k]);
  struct sigaction dfl {};
  dfl.sa_handler = SIG_DFL;
  sigemptyset(&dfl.sa_mask);
  ::sigaction(sig, &dfl, nullptr);
  ::raise(sig);
}

std::string kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISLNK(mode)) return "a symbolic link";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

}  // namespace

void install_temporary_cleanup() {
  static const bool installed = [] {
    for (int sig : kSignals) {
      struct sigaction old {};
      if (::sigaction(sig, nullptr, &old) != 0 || old.sa_handler != SIG_DFL) continue;  // keep SIG_IGN and others
      struct sigaction sa {};
      sa.sa_handler = remove_temporaries_and_reraise;
      sigemptyset(&sa.sa_mask);
      ::sigaction(sig, &sa, nullptr);
    }
    return true;
  }();
  (void)installed;
}

int registered_temporaries() {
  int n = 0;
  for (int k = 0; k < kSlots; ++k) n += slot_state[k].load() == 2;
  return n;
}

void check_output_target(const std::filesystem::path& target) {
  struct stat st {};
  if (::lstat(target.c_str(), &st) != 0) return;  // absent (or unreachable: the open reports it)
  if (!S_ISREG(st.st_mode))
    throw InputError(target.string(), "exists and is " + kind_of(st.st_mode) +
                                          "; refusing to replace it with an output file (give a file name)");
}

std::filesystem::path temporary_path_for(const std::filesystem::path& target) {
  check_output_target(target);
  install_temporary_cleanup();
  std::filesystem::path tmp = target;
  tmp += ".tmp." + std::to_string(::getpid());
  register_temporary(tmp);
  return tmp;
}

void discard_temporary(const std::filesystem::path& temporary) {
  std::error_code ec;
  std::filesystem::remove(temporary, ec);
  forget_temporary(temporary);
}

void commit_file(const std::filesystem::path& temporary, const std::filesystem::path& target) {
  try {
    check_output_target(target);
  } catch (...) {
    discard_temporary(temporary);
    throw;
  }
  std::error_code ec;
  std::filesystem::rename(temporary, target, ec);
  if (ec) {
    discard_temporary(temporary);
    throw OutputError(target.string() + ": cannot rename " + temporary.string() + " onto it: " + ec.message());
  }
  forget_temporary(temporary);
}

AtomicTextFile::AtomicTextFile(std::filesystem::path target)
    : target_(std::move(target)), temporary_(temporary_path_for(target_)) {
  stream_.open(temporary_, std::ios::out | std::ios::trunc);
  if (!stream_) {
    forget_temporary(temporary_);
    throw OutputError(target_.string() + ": cannot open for writing (" + std::strerror(errno) + ")");
  }
}

AtomicTextFile::~AtomicTextFile() {
  if (!committed_) {
    stream_.close();
    discard_temporary(temporary_);
  }
}

void AtomicTextFile::commit() {
  stream_.flush();
  if (!stream_) throw OutputError(target_.string() + ": write failed (" + std::strerror(errno) + ")");
  stream_.close();
  if (stream_.fail()) throw OutputError(target_.string() + ": closing the file failed (" + std::strerror(errno) + ")");
  commit_file(temporary_, target_);
  committed_ = true;
}

}  // namespace common
