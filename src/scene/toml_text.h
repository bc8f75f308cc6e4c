#pragma once
// Values written as TOML text, for files cablefilm writes by hand (with comments, which a
// TOML library's writer drops): a string quoted and escaped, a number that reads back as the
// same double.
#include <string>

namespace cablefilm {

// A TOML basic string: "..." with \" \\ and the control characters escaped; a byte that is
// not part of well-formed UTF-8 becomes U+FFFD (a TOML file is UTF-8).
std::string TomlString(const std::string& text);

// The shortest decimal that reads back as v, always with a "." or an exponent so that TOML
// takes it as a float ("850.0", "7.5e+08", "0.137"); -0 is written 0.0. v must be finite.
std::string TomlNumber(double v);

}  // namespace cablefilm
