#pragma once
// The scene fuzzer's target (scene_fuzzer.cpp), shared by the libFuzzer build and the standalone
// replay driver (replay_main.cpp).
#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv);
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace cablefilm_fuzz {

// How each input ended. Every one of them is an acceptable end: a failure (a sanitizer report,
// an exception other than cablefilm::Error, a hang) aborts the process instead.
struct Counts {
  long inputs = 0;
  long rejected = 0;       // refused cleanly by the loader or `check` (cablefilm::Error)
  long not_toml = 0;       //   of which the scene is not TOML (the parser's rejections)
  long loaded_only = 0;    // accepted by the loader, too many links to check here
  long checked_only = 0;   // accepted by `check`, too many links to simulate here
  long simulated = 0;      // accepted and simulated (the first outputs of every model run)
  long systems = 0;        //   of which systems of lines (their system's run)
  long run_errors = 0;     //   of which one ended in a clean error (blow-up, no equilibrium)
  long budget_cut = 0;     //   of which one stopped at the fuzzer's time budget
};
const Counts& GetCounts();
void PrintCounts();  // on stderr

}  // namespace cablefilm_fuzz
