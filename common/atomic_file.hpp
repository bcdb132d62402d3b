#pragma once
// Output files that never look complete when they are not: write to "<name>.tmp.<pid>", then rename.
// The target must be absent or a regular file: a directory, device, FIFO, socket or symbolic link is
// never replaced. Temporaries are registered while they exist, and SIGTERM / SIGINT / SIGHUP remove
// them before the process dies (install_temporary_cleanup()).
#include <filesystem>
#include <fstream>

namespace common {

/// Throws common::InputError naming `target` when it exists and is not a regular file (checked with
/// lstat, so a symbolic link is refused too, whatever it points to).
void check_output_target(const std::filesystem::path& target);

/// Temporary sibling path for `target` ("<target>.tmp.<pid>"), after check_output_target(target);
/// the path is registered for removal on SIGTERM/SIGINT/SIGHUP. Rename it onto `target` when done.
std::filesystem::path temporary_path_for(const std::filesystem::path& target);

/// Atomically replace `target` by `temporary` (same directory, so rename(2) is atomic); the target
/// is checked again just before the rename. Throws std::runtime_error naming both paths on failure
/// (common::InputError when the target is not a regular file); the temporary is removed then.
void commit_file(const std::filesystem::path& temporary, const std::filesystem::path& target);

/// Removes `temporary` (if it exists) and forgets it.
void discard_temporary(const std::filesystem::path& temporary);

/// Installs the SIGTERM/SIGINT/SIGHUP handler that unlinks the registered temporaries (only
/// async-signal-safe calls: unlink, sigaction, raise) and then re-raises the signal with its default
/// action, so the exit status still says "killed by signal". Idempotent; temporary_path_for calls it.
/// A signal the process ignores (SIG_IGN, e.g. under nohup) stays ignored.
void install_temporary_cleanup();

/// Number of temporaries registered now (for tests).
int registered_temporaries();

/// A text output file written to a temporary name and renamed onto its target by commit().
/// If commit() is never called (an exception unwinds), the temporary is removed and the
/// target is left untouched.
class AtomicTextFile {
 public:
  explicit AtomicTextFile(std::filesystem::path target);
  AtomicTextFile(const AtomicTextFile&) = delete;
  AtomicTextFile& operator=(const AtomicTextFile&) = delete;
  ~AtomicTextFile();

  std::ofstream& stream() { return stream_; }
  /// Flush, close and rename onto the target. Throws on any I/O failure (common::OutputError).
  void commit();

 private:
  std::filesystem::path target_;
  std::filesystem::path temporary_;
  std::ofstream stream_;
  bool committed_ = false;
};

}  // namespace common
