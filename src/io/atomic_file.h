#pragma once
// An output file that appears whole or not at all: everything is written to a temporary file
// beside the target, which Commit() renames over the target. Destroyed uncommitted, the
// temporary file is removed, so an interrupted or failed run never leaves a truncated result
// under the final name.
#include <cstdio>
#include <string>

namespace cablefilm {

class AtomicFile {
 public:
  explicit AtomicFile(std::string path);  // throws Error if the temporary file cannot be created
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  std::FILE* stream() { return file_; }
  const std::string& temp_path() const { return temp_path_; }
  const std::string& path() const { return path_; }

  // Flushes, closes and renames to `path()` (or to `other_path` when given). Throws Error with
  // the file name on any write error.
  void Commit();
  void CommitAs(const std::string& other_path);

 private:
  std::string path_;
  std::string temp_path_;
  std::FILE* file_ = nullptr;
  bool committed_ = false;
};

}  // namespace cablefilm
