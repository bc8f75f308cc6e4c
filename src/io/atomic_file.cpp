#include "io/atomic_file.h"

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <unistd.h>

#include "core/error.h"
#include "io/output_ledger.h"

namespace cablefilm {

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)) {
  temp_path_ = path_ + ".tmp" + std::to_string(::getpid());
  RecordOutput(path_);  // before its temporary exists: a kill leaves nothing unlisted
  file_ = std::fopen(temp_path_.c_str(), "wb");
  if (!file_) throw Error("cannot create " + temp_path_ + ": " + std::strerror(errno));
}

AtomicFile::~AtomicFile() {
  if (file_) std::fclose(file_);
  if (!committed_) std::remove(temp_path_.c_str());
}

void AtomicFile::Commit() { CommitAs(path_); }

void AtomicFile::CommitAs(const std::string& other_path) {
  if (committed_) throw Error("internal: " + path_ + " committed twice");
  if (other_path != path_) RecordOutput(other_path);
  const bool write_failed = std::ferror(file_) != 0;
  const bool close_failed = std::fclose(file_) != 0;
  file_ = nullptr;
  if (write_failed || close_failed)
    throw Error("error writing " + temp_path_ + " (disk full?); " + other_path + " not written");
  if (std::rename(temp_path_.c_str(), other_path.c_str()) != 0)
    throw Error("cannot rename " + temp_path_ + " to " + other_path + ": " + std::strerror(errno));
  committed_ = true;
}

}  // namespace cablefilm
