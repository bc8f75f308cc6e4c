#pragma once
// The layout of a MoorDyn input file, before any value is read: the free text at the top,
// then sections, each announced by a header line of dashes around a key phrase ("----- LINE
// TYPES -----"), a table section's two lines of column names and units skipped as MoorDyn
// skips them, and every other line that holds something after its comment cut off (#, ! or
// %, MoorDyn's comment characters) kept as a row of whitespace-separated words.
#include <string>
#include <vector>

namespace cablefilm {

enum class MoorDynSection {
  kLineTypes, kRodTypes, kBodies, kRods, kPoints, kLines, kOptions, kOutputs,
  kEnd,    // "need this line": nothing after it is read
  kOther,  // a header MoorDyn's v2 reader does not know, or one cablefilm does not read
};

// The section's name as messages show it: "LINE TYPES", "POINTS", ...
const char* MoorDynSectionName(MoorDynSection section);

struct MoorDynRowText {
  int line = 0;                     // of the file, 1-based
  std::vector<std::string> words;   // at least one
};

struct MoorDynSectionText {
  MoorDynSection kind = MoorDynSection::kOther;
  std::string phrase;   // the header's key phrase as written, dashes trimmed
  int line = 0;         // the header's line
  std::vector<MoorDynRowText> rows;
};

struct MoorDynLayout {
  std::string title;    // the first non-empty line of the free text at the top, trimmed
  int last_line = 0;
  std::vector<MoorDynSectionText> sections;  // in the file's order, kEnd and after left out
  std::vector<std::string> warnings;
};

// Throws Error "file:line: ..." for an empty file and a section given twice; `file` is the
// name as messages show it (already escaped).
MoorDynLayout SplitMoorDynText(const std::string& text, const std::string& file);

}  // namespace cablefilm
