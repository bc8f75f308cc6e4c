#pragma once
// The one error type of the program: thrown with its full context (file, key, time, station)
// and caught once, in main, which prints it and exits non-zero.
#include <stdexcept>
#include <string>

namespace cablefilm {

class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& what) : std::runtime_error(what) {}
};

}  // namespace cablefilm
