#pragma once
// The values a front end's options take (`run --size`, `live --fps`, ...), checked against the
// same limits as the scene's keys, each refusal naming the option and quoting what was typed
// (escaped) as a UsageError: the command line answers it with exit status 2.
#include <stdexcept>
#include <string>

namespace cablefilm {

// A bad option or argument; the message names it and quotes what the user typed.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

[[noreturn]] void Bad(const std::string& message);  // throws UsageError
std::string Shown(const std::string& text);        // as a message quotes it

// A finite decimal number, nothing before or after it.
bool ParseDouble(const std::string& text, double* v);
// A finite number within [lo, hi] (lo itself excluded when lo_open).
double ParseNumber(const std::string& option, const std::string& text, double lo, double hi,
                   bool lo_open, const std::string& unit);
// WxH: even whole numbers within the stated pixel limits (checked before anything is drawn).
void ParseSize(const std::string& option, const std::string& text, int* width, int* height);
std::string ParseColormap(const std::string& option, const std::string& text);
std::string ParseView(const std::string& option, const std::string& text);
// A folder, checked now rather than after the simulation, when the film needs it.
std::string ParseShaderDir(const std::string& option, const std::string& text);
// MIN,MAX in N, 0 <= MIN < MAX <= the largest tension.
void ParseTensionRange(const std::string& option, const std::string& text, double* lo,
                       double* hi);

}  // namespace cablefilm
