#include "common/atomic_file.hpp"

#include <stdexcept>
#include <system_error>
#include <unistd.h>

namespace common {

std::filesystem::path temporary_path_for(const std::filesystem::path& target) {
  std::filesystem::path tmp = target;
  tmp += ".tmp." + std::to_string(::getpid());
  return tmp;
}

void commit_file(const std::filesystem::path& temporary, const std::filesystem::path& target) {
  std::error_code ec;
  std::filesystem::rename(temporary, target, ec);
  if (ec) {
    std::filesystem::remove(temporary, ec);
    throw std::runtime_error(target.string() + ": cannot rename " + temporary.string() +
                             " onto it: " + ec.message());
  }
}

AtomicTextFile::AtomicTextFile(std::filesystem::path target)
    : target_(std::move(target)), temporary_(temporary_path_for(target_)) {
  stream_.open(temporary_, std::ios::out | std::ios::trunc);
  if (!stream_) throw std::runtime_error(target_.string() + ": cannot open for writing");
}

AtomicTextFile::~AtomicTextFile() {
  if (!committed_) {
    stream_.close();
    std::error_code ec;
    std::filesystem::remove(temporary_, ec);
  }
}

void AtomicTextFile::commit() {
  stream_.flush();
  if (!stream_) throw std::runtime_error(target_.string() + ": write failed");
  stream_.close();
  commit_file(temporary_, target_);
  committed_ = true;
}

}  // namespace common
