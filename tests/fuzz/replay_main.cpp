// The scene fuzzer without libFuzzer: runs its target once on each file given, or on each file
// of each folder given (sorted by name), so that the corpus and every input that ever failed run
// as an ordinary test in any build (GCC or clang, optimised or sanitized).
//   scene_fuzz_replay [--timeout SECONDS] FILE_OR_FOLDER...
// Exits 0 when every input ends cleanly; a failure aborts (the target's message or a sanitizer
// report names the input on the line before it); an input still running after the timeout
// (default 60 s) ends the driver with status 70, naming it.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "scene_fuzzer.h"

namespace {

namespace fs = std::filesystem;

char g_current[4096] = "";

extern "C" void OnAlarm(int) {
  const char before[] = "\nscene_fuzz_replay: TIMEOUT (a hang): ";
  ssize_t ignored = ::write(2, before, sizeof before - 1);
  ignored = ::write(2, g_current, std::strlen(g_current));
  ignored = ::write(2, "\n", 1);
  (void)ignored;
  ::_exit(70);
}

}  // namespace

int main(int argc, char** argv) {
  unsigned timeout = 60;
  std::vector<fs::path> files;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--timeout" && i + 1 < argc) {
      timeout = static_cast<unsigned>(std::atoi(argv[++i]));
      continue;
    }
    std::error_code ec;
    if (fs::is_directory(arg, ec)) {
      std::vector<fs::path> in;
      for (const auto& e : fs::directory_iterator(arg, ec))
        if (e.is_regular_file() && e.path().filename().string()[0] != '.') in.push_back(e.path());
      std::sort(in.begin(), in.end());
      files.insert(files.end(), in.begin(), in.end());
    } else if (fs::is_regular_file(arg, ec)) {
      files.emplace_back(arg);
    } else {
      std::fprintf(stderr, "scene_fuzz_replay: %s: no such file or folder\n", arg.c_str());
      return 2;
    }
  }
  if (files.empty()) {
    std::fprintf(stderr, "usage: scene_fuzz_replay [--timeout SECONDS] FILE_OR_FOLDER...\n");
    return 2;
  }
  LLVMFuzzerInitialize(&argc, &argv);
  std::signal(SIGALRM, OnAlarm);
  double slowest = 0;
  std::string slowest_name;
  for (const fs::path& p : files) {
    std::snprintf(g_current, sizeof g_current, "%s", p.c_str());
    std::ifstream in(p, std::ios::binary);
    const std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::fprintf(stderr, "%s (%zu bytes): ", p.c_str(), data.size());
    const cablefilm_fuzz::Counts before = cablefilm_fuzz::GetCounts();
    const auto t0 = std::chrono::steady_clock::now();
    ::alarm(timeout);
    LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(data.data()), data.size());
    ::alarm(0);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const cablefilm_fuzz::Counts& after = cablefilm_fuzz::GetCounts();
    const char* end = after.rejected > before.rejected           ? "rejected"
                      : after.loaded_only > before.loaded_only   ? "loaded, too large to check"
                      : after.checked_only > before.checked_only ? "checked, too large to run"
                      : after.budget_cut > before.budget_cut     ? "ran, stopped at the budget"
                      : after.run_errors > before.run_errors     ? "ran, ended in an error"
                                                                 : "ran";
    std::fprintf(stderr, "%s, %.3f s\n", end, s);
    if (s > slowest) {
      slowest = s;
      slowest_name = p.string();
    }
  }
  std::fprintf(stderr,
               "scene_fuzz_replay: every input ended cleanly; the slowest took %.3f s (%s)\n",
               slowest, slowest_name.c_str());
  return 0;  // the counts are printed at exit
}
