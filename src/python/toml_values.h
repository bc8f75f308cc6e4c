#pragma once
// Python values to and from TOML, through toml++: a scene given as a dict (the schema of the
// TOML file: nested dicts, lists, numbers, strings, booleans) becomes TOML text that the
// scene loader reads as it reads a file, so its checks and messages are the same.
#include <pybind11/pybind11.h>

#include <string>

namespace cablefilm::python {

// The TOML document of a dict (keys str; values bool, int, float, str, dict, list, tuple,
// numpy scalars and arrays). Throws TypeError naming the key of a value TOML cannot hold.
std::string DictToToml(const pybind11::dict& scene);

// One value as TOML text on one line ("0.5", "[1.0, 0.0]", "\"explicit\"", "{ a = 1 }"), for
// a scene key. `key` names it in a TypeError.
std::string ValueToToml(const pybind11::handle& value, const std::string& key);

// The value "v" of a TOML document as a Python value (tables as dicts, arrays as lists).
pybind11::object TomlDocumentValue(const std::string& document);

// A whole TOML document as a dict.
pybind11::dict TomlToDict(const std::string& text);

}  // namespace cablefilm::python
