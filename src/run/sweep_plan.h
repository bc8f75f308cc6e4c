#pragma once
// The cases of a sweep: which scene keys take which values (the --set options, a CSV of cases,
// or the Python module's dict), expanded to one row of values per case; each case's scene is
// the original edited with them (scene/scene_edit.h). Shared by the command line's sweep and
// the Python module's.
#include <string>
#include <vector>

namespace cablefilm {

// At most this many cases in one sweep (the cross product is checked before it is built).
constexpr double kMaxSweepCases = 1e5;

// One --set: a key and its values, each value's text as given (trimmed).
struct SweepKey {
  std::string key;
  std::vector<std::string> values;
};

// At most this many values in one range A..B of a --set.
constexpr double kMaxSweepRange = 10000;

// "KEY=V1,V2,...": the values split at the commas outside brackets, braces and quotes; a value
// A..B (whole numbers, A <= B) stands for A, A+1, ..., B (ExpandWholeRange). Throws Error with
// a message naming the key (or the option) when the key is no dotted path, a value is no TOML
// value or a range is bad.
SweepKey ParseSetOption(const std::string& text);

// The whole numbers A, A+1, ..., B of "A..B" (spaces allowed around each), as texts. Throws
// Error naming `key` when A or B is no whole number, B < A, or there are more than
// kMaxSweepRange of them.
std::vector<std::string> ExpandWholeRange(const std::string& range, const std::string& key);

// The cases: keys (columns) and one row of value texts per case.
struct SweepCases {
  std::vector<std::string> keys;
  std::vector<std::vector<std::string>> rows;
};

// A CSV of cases (RFC 4180: commas, double quotes around a cell that holds commas): a header
// naming the keys, then one row of values per case. Throws Error naming the file and the line.
SweepCases ReadCasesCsv(const std::string& path);

// The cases: every row of `listed` (none: one empty case) times the cross product of `sets`,
// the first --set varying slowest. Throws Error on a key given twice or too many cases.
SweepCases ExpandCases(const SweepCases& listed, const std::vector<SweepKey>& sets);

// Case folder names: case_000, case_001, ... (more digits beyond 1000 cases).
std::string CaseFolderName(size_t index, size_t count);

// A CSV cell: quoted when it holds a comma, a quote or a line break.
std::string CsvCell(const std::string& text);

}  // namespace cablefilm
