#pragma once
// Scratch folders shared by the C++ tests (one folder per test process, so test binaries running in
// parallel never share files).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <mutex>
#include <string>
#include <system_error>
#include <vector>

namespace test_support {

/// The scratch folders of this process, removed when it exits with every test passed: a failed test's
/// files stay to be looked at, and a passing suite leaves nothing behind (gtest_discover_tests runs
/// one process per test, so the folders would otherwise pile up in the temp folder).
class ScratchCleanup {
 public:
  static void add(const std::filesystem::path& dir) {
    ::testing::UnitTest::GetInstance();  // constructed first, so destroyed after the cleanup below
    static ScratchCleanup cleanup;
    const std::lock_guard<std::mutex> lock(cleanup.mutex_);
    cleanup.dirs_.push_back(dir);
  }
  ~ScratchCleanup() {
    if (!::testing::UnitTest::GetInstance()->Passed()) return;
    std::error_code ec;
    for (const auto& dir : dirs_) std::filesystem::remove_all(dir, ec);
  }

 private:
  ScratchCleanup() = default;
  std::mutex mutex_;
  std::vector<std::filesystem::path> dirs_;
};

/// <system temp folder>/<prefix>_<pid>, created if missing; its files are kept until the process
/// exits (ScratchCleanup).
inline std::filesystem::path scratch_folder(const std::string& prefix) {
  const auto dir = std::filesystem::temp_directory_path() / (prefix + "_" + std::to_string(::getpid()));
  if (std::filesystem::create_directories(dir)) ScratchCleanup::add(dir);
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
