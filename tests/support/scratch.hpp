#pragma once
// Scratch folders shared by the C++ tests (one folder per test process, so test binaries running in
// parallel never share files).
#include <unistd.h>

#include <filesystem>
#include <string>
#include <system_error>

namespace test_support {

/// <system temp folder>/<prefix>_<pid>, created if missing (its files are kept).
inline std::filesystem::path scratch_folder(const std::string& prefix) {
  const auto dir = std::filesystem::temp_directory_path() / (prefix + "_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  return dir;
}

/// An empty folder `name` inside scratch_folder(prefix) (removed first when it exists).
inline std::filesystem::path fresh_scratch_folder(const std::string& prefix, const std::string& name) {
  const auto dir = scratch_folder(prefix) / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

/// A fresh scratch folder <system temp folder>/<name>_<pid>, removed by the destructor.
class ScratchDir {
 public:
  explicit ScratchDir(const std::string& name) : path_(scratch_folder(name)) {
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  ~ScratchDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace test_support
