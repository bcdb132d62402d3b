#pragma once
// Output files that never look complete when they are not: write to "<name>.tmp.<pid>", then rename.
#include <filesystem>
#include <fstream>

namespace common {

/// Temporary sibling path for `target` ("<target>.tmp.<pid>"); rename it onto `target` when done.
std::filesystem::path temporary_path_for(const std::filesystem::path& target);

/// Atomically replace `target` by `temporary` (same directory, so rename(2) is atomic).
/// Throws std::runtime_error naming both paths on failure.
void commit_file(const std::filesystem::path& temporary, const std::filesystem::path& target);

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
  /// Flush, close and rename onto the target. Throws on any I/O failure.
  void commit();

 private:
  std::filesystem::path target_;
  std::filesystem::path temporary_;
  std::ofstream stream_;
  bool committed_ = false;
};

}  // namespace common
