#include "io/output_ledger.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <set>
#include <vector>

#include "core/error.h"
#include "io/out_dir_lock.h"
#include "scene/text_escape.h"

namespace cablefilm {

const char OutputLedger::kFileName[] = ".cablefilm.written";

namespace fs = std::filesystem;

namespace {

const char kHeader[] =
    "# cablefilm: the files and folders its last run here wrote; the next run removes these "
    "and nothing else\n";

struct OpenLedger {
  fs::path folder;  // canonical
  std::FILE* file = nullptr;
  std::set<std::string> written;
};

std::mutex g_mutex;
OutputRecorder g_recorder = nullptr;  // the program's, in a module
std::vector<OpenLedger> g_open;  // few: one per folder a process writes into at once

// `p` with its folders resolved (symlinks, "..") but its own name kept: a link named like a
// result is replaced by the result, not followed.
fs::path Resolved(const fs::path& p) {
  std::error_code ec;
  const fs::path absolute = fs::absolute(p, ec).lexically_normal();
  fs::path name = absolute.filename();
  fs::path parent = absolute.parent_path();
  if (name.empty()) {  // "dir/"
    name = parent.filename();
    parent = parent.parent_path();
  }
  const fs::path resolved = fs::weakly_canonical(parent, ec);
  return (ec ? parent : resolved) / name;
}

// `rel` split into plain names when it is a path inside a folder (no root, "." or ".."):
// what a ledger may list, whoever edited it.
bool PlainNames(const std::string& rel, std::vector<std::string>* names) {
  names->clear();
  if (rel.empty() || rel.front() == '/') return false;
  std::size_t start = 0;
  while (start < rel.size()) {
    std::size_t end = rel.find('/', start);
    if (end == std::string::npos) end = rel.size();
    const std::string name = rel.substr(start, end - start);
    if (name.empty() || name == "." || name == "..") return false;
    names->push_back(name);
    start = end + 1;
  }
  return !names->empty();
}

// `folder`/`names`, when every folder on the way is a real folder (no link leads out).
bool RealPathInside(const fs::path& folder, const std::vector<std::string>& names, fs::path* p) {
  std::error_code ec;
  *p = folder;
  for (std::size_t i = 0; i + 1 < names.size(); ++i) {
    *p /= names[i];
    if (!fs::is_directory(fs::symlink_status(*p, ec))) return false;
  }
  *p /= names.back();
  return true;
}

// "NAME.tmpPID": a temporary file of NAME left by a killed run.
bool IsTemporaryOf(const std::string& entry, const std::string& name) {
  const std::string prefix = name + ".tmp";
  if (entry.size() <= prefix.size() || entry.compare(0, prefix.size(), prefix) != 0) return false;
  return std::all_of(entry.begin() + static_cast<long>(prefix.size()), entry.end(),
                     [](char c) { return c >= '0' && c <= '9'; });
}

// A lock file that no run holds (a killed run's): removed.
void RemoveFreeLock(const fs::path& folder) {
  const fs::path path = folder / OutDirLock::kFileName;
  const int fd = ::open(path.c_str(), O_RDWR | O_CLOEXEC | O_NOFOLLOW);
  if (fd < 0) return;
  if (::flock(fd, LOCK_EX | LOCK_NB) == 0) ::unlink(path.c_str());
  ::close(fd);
}

void RemoveRecordedIn(const fs::path& folder, int depth) {
  std::error_code ec;
  const fs::path ledger = folder / OutputLedger::kFileName;
  if (!fs::is_regular_file(fs::symlink_status(ledger, ec))) return;
  std::ifstream in(ledger);
  std::map<fs::path, std::set<std::string>> files;  // folder -> names of the files in it
  std::vector<std::pair<std::size_t, fs::path>> folders;  // (depth, path)
  std::vector<std::string> names;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line.front() == '#') continue;
    const bool is_folder = line.back() == '/';
    if (is_folder) line.pop_back();
    fs::path p;
    if (!PlainNames(line, &names) || !RealPathInside(folder, names, &p)) continue;
    if (is_folder)
      folders.emplace_back(names.size(), p);
    else
      files[p.parent_path()].insert(names.back());
  }
  in.close();
  for (const auto& [dir, in_dir] : files) {
    for (const std::string& name : in_dir) {
      const fs::path p = dir / name;
      if (!fs::is_regular_file(fs::symlink_status(p, ec))) continue;  // ours are plain files
      fs::remove(p, ec);
      if (ec)
        throw Error("cannot remove the earlier result " + EscapeText(p.string()) + ": " +
                    ec.message());
    }
    if (!fs::is_directory(fs::symlink_status(dir, ec))) continue;
    std::vector<fs::path> temporaries;
    for (const auto& entry : fs::directory_iterator(dir, ec)) {
      const std::string entry_name = entry.path().filename().string();
      for (const std::string& name : in_dir)
        if (IsTemporaryOf(entry_name, name) && entry.is_regular_file(ec))
          temporaries.push_back(entry.path());
    }
    for (const fs::path& p : temporaries) fs::remove(p, ec);
  }
  // Deepest first, so that a folder's own folders go before it.
  std::sort(folders.begin(), folders.end(),
            [](const auto& a, const auto& b) { return a.first > b.first; });
  for (const auto& [unused, p] : folders) {
    if (!fs::is_directory(fs::symlink_status(p, ec))) continue;
    if (depth < 8) RemoveRecordedIn(p, depth + 1);  // a run's folder inside a sweep's
    RemoveFreeLock(p);
    if (fs::is_empty(p, ec)) fs::remove(p, ec);
  }
  fs::remove(ledger, ec);
}

}  // namespace

void RemoveRecordedOutputs(const std::string& folder) { RemoveRecordedIn(folder, 0); }

void OutputLedger::Open(const std::string& folder) {
  Close();
  RemoveRecordedOutputs(folder);
  const fs::path path = fs::path(folder) / kFileName;
  const int fd =
      ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_APPEND | O_CLOEXEC | O_NOFOLLOW, 0644);
  std::FILE* file = fd < 0 ? nullptr : ::fdopen(fd, "a");
  if (!file || std::fputs(kHeader, file) < 0 || std::fflush(file) != 0) {
    const int error = errno;
    if (file) std::fclose(file);
    else if (fd >= 0) ::close(fd);
    throw Error("cannot write " + EscapeText(path.string()) + ", the list of what a run writes "
                "in its folder: " + std::strerror(error));
  }
  std::lock_guard<std::mutex> hold(g_mutex);
  OpenLedger open;
  open.folder = Resolved(fs::path(folder) / "");
  open.file = file;
  folder_ = open.folder.string();
  g_open.push_back(std::move(open));
}

OutputLedger::~OutputLedger() { Close(); }

void OutputLedger::Close() {
  if (folder_.empty()) return;
  std::lock_guard<std::mutex> hold(g_mutex);
  for (auto it = g_open.begin(); it != g_open.end(); ++it)
    if (it->folder.string() == folder_) {
      std::fclose(it->file);
      g_open.erase(it);
      break;
    }
  folder_.clear();
}

void RecordOutputsThrough(OutputRecorder recorder) {
  std::lock_guard<std::mutex> hold(g_mutex);
  g_recorder = recorder;
}

std::string RecordOutputOrSay(const std::string& path) {
  try {
    RecordOutput(path);
    return "";
  } catch (const std::exception& e) {
    return e.what();
  }
}

void RecordOutput(const std::string& path) {
  OutputRecorder recorder = nullptr;
  {
    std::lock_guard<std::mutex> hold(g_mutex);
    recorder = g_recorder;
  }
  if (recorder) {
    const std::string error = recorder(path);
    if (!error.empty()) throw Error(error);
    return;
  }
  std::lock_guard<std::mutex> hold(g_mutex);
  if (g_open.empty()) return;
  const bool is_folder = !path.empty() && path.back() == '/';
  const fs::path p = Resolved(path);
  for (OpenLedger& open : g_open) {
    const fs::path rel = p.lexically_relative(open.folder);
    const std::string text = rel.generic_string();
    if (rel.empty() || text == "." || text.rfind("..", 0) == 0) continue;
    // A name with a line break cannot be listed: it is then never removed, which is safe.
    if (text.find_first_of("\r\n") != std::string::npos) return;
    const std::string entry = text + (is_folder ? "/" : "");
    if (!open.written.insert(entry).second) return;
    if (std::fprintf(open.file, "%s\n", entry.c_str()) < 0 || std::fflush(open.file) != 0)
      throw Error("cannot write " + EscapeText((open.folder / OutputLedger::kFileName).string()) +
                  ", the list of what a run writes in its folder: " + std::strerror(errno) +
                  "; " + EscapeText(path) + " not written");
    return;
  }
}

void CreateOutputFolder(const std::string& folder) {
  std::error_code ec;
  std::vector<fs::path> missing;
  for (fs::path p = fs::absolute(folder, ec).lexically_normal(); !p.empty();
       p = p.parent_path()) {
    if (p.filename().empty()) continue;  // "dir/" ends with an empty name
    if (fs::exists(fs::symlink_status(p, ec))) break;
    missing.push_back(p);
    if (p == p.parent_path()) break;
  }
  for (auto it = missing.rbegin(); it != missing.rend(); ++it) RecordOutput(it->string() + "/");
  fs::create_directories(folder, ec);
  if (ec) throw Error("cannot create the folder " + EscapeText(folder) + ": " + ec.message());
}

}  // namespace cablefilm
