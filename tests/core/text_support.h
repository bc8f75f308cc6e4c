#pragma once
// Small text helpers the tests share: a whole file as a string, and a checked replacement
// (a scene text edited for one test case must contain what the test means to change).
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

namespace cablefilm_test {

inline std::string ReadText(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

inline std::string Replace(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  if (at == std::string::npos) throw std::logic_error("test bug: \"" + from + "\" not found");
  return text.replace(at, from.size(), to);
}

}  // namespace cablefilm_test
