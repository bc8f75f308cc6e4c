#include "scene/moordyn_layout.h"

#include <cctype>
#include <map>

#include "core/error.h"
#include "scene/text_escape.h"

namespace cablefilm {
namespace {

// The file's lines, "\n" or "\r\n" ended; a UTF-8 byte order mark at the start dropped.
std::vector<std::string> SplitLines(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t start = text.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;
  while (start <= text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    std::string line = text.substr(start, end - start);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(std::move(line));
    start = end + 1;
  }
  if (!lines.empty() && lines.back().empty()) lines.pop_back();  // the final newline's
  return lines;
}

// MoorDyn's comment characters: the rest of the line is not read.
std::string StripComment(const std::string& line) {
  return line.substr(0, line.find_first_of("#!%"));
}

std::vector<std::string> Words(const std::string& text) {
  std::vector<std::string> words;
  const char* blanks = " \t\r\v\f";
  std::size_t at = text.find_first_not_of(blanks);
  while (at != std::string::npos) {
    const std::size_t end = text.find_first_of(blanks, at);
    words.push_back(text.substr(at, end == std::string::npos ? end : end - at));
    at = end == std::string::npos ? end : text.find_first_not_of(blanks, end);
  }
  return words;
}

std::string Join(const std::vector<std::string>& words) {
  std::string out;
  for (const auto& w : words) out += (out.empty() ? "" : " ") + w;
  return out;
}

std::string Trim(const std::string& text) { return Join(Words(text)); }

std::string Upper(std::string text) {
  for (char& c : text) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return text;
}

// The header's key phrase: its dashes dropped, blanks collapsed.
std::string Phrase(const std::string& header) {
  std::string text = header;
  for (char& c : text)
    if (c == '-') c = ' ';
  return Trim(text);
}

// Whether `name`'s words stand one after the other, whole, among the phrase's words
// ("SOLVER OPTIONS" holds "OPTIONS"; "LINE TYPES" does not hold "LINES").
bool HoldsName(const std::vector<std::string>& phrase, const std::vector<std::string>& name) {
  for (std::size_t i = 0; i + name.size() <= phrase.size(); ++i) {
    std::size_t k = 0;
    while (k < name.size() && phrase[i + k] == name[k]) ++k;
    if (k == name.size()) return true;
  }
  return false;
}

// MoorDyn's key phrases for each section (MoorDyn2.cpp, ReadInFile), matched whole-word and
// case-insensitively.
MoorDynSection SectionOf(const std::string& phrase) {
  static const std::vector<std::pair<MoorDynSection, std::vector<std::string>>> kNames = {
      {MoorDynSection::kLineTypes, {"LINE DICTIONARY", "LINE TYPES"}},
      {MoorDynSection::kRodTypes, {"ROD DICTIONARY", "ROD TYPES"}},
      {MoorDynSection::kBodies, {"BODIES", "BODY LIST", "BODY PROPERTIES"}},
      {MoorDynSection::kRods, {"RODS", "ROD LIST", "ROD PROPERTIES"}},
      {MoorDynSection::kPoints,
       {"POINTS", "POINT LIST", "POINT PROPERTIES", "CONNECTION PROPERTIES", "NODE PROPERTIES"}},
      {MoorDynSection::kLines, {"LINES", "LINE LIST", "LINE PROPERTIES"}},
      {MoorDynSection::kOptions, {"OPTIONS"}},
      {MoorDynSection::kOutputs, {"OUTPUTS", "OUTPUT"}},
      {MoorDynSection::kEnd, {"NEED THIS LINE"}},
  };
  const std::vector<std::string> words = Words(Upper(phrase));
  for (const auto& [section, names] : kNames)
    for (const std::string& name : names)
      if (HoldsName(words, Words(name))) return section;
  return MoorDynSection::kOther;
}

// A table's column names and units: the two lines after its header, read by nobody.
bool HasColumnHeaders(MoorDynSection section) {
  return section != MoorDynSection::kOptions && section != MoorDynSection::kOutputs &&
         section != MoorDynSection::kOther;
}

std::string At(const std::string& file, int line) {
  return file + ":" + std::to_string(line) + ": ";
}

void CheckNotEmpty(const std::vector<std::string>& lines, const std::string& file) {
  for (const std::string& line : lines)
    if (!Words(line).empty()) return;
  throw Error(At(file, 1) + "the file is empty; expected a MoorDyn v2 input file (sections "
              "LINE TYPES, POINTS, LINES and OPTIONS)");
}

// What follows MoorDyn's closing header is never read: say so if it holds anything.
void WarnAfterEnd(const std::vector<std::string>& lines, std::size_t end, const std::string& file,
                  std::vector<std::string>* warnings) {
  for (std::size_t i = end + 1; i < lines.size(); ++i)
    if (!Words(StripComment(lines[i])).empty()) {
      warnings->push_back(At(file, static_cast<int>(i + 1)) + "not read: it follows the "
                          "closing header (line " + std::to_string(end + 1) + ")");
      return;
    }
}

void WarnSkippedSections(const MoorDynLayout& layout, const std::string& file,
                         std::vector<std::string>* warnings) {
  for (const MoorDynSectionText& s : layout.sections)
    if (s.kind == MoorDynSection::kOther)
      warnings->push_back(At(file, s.line) + "section " + QuoteText(s.phrase) + " (" +
                          std::to_string(s.rows.size()) +
                          " lines) skipped: not a section cablefilm reads");
}

}  // namespace

const char* MoorDynSectionName(MoorDynSection section) {
  switch (section) {
    case MoorDynSection::kLineTypes: return "LINE TYPES";
    case MoorDynSection::kRodTypes: return "ROD TYPES";
    case MoorDynSection::kBodies: return "BODIES";
    case MoorDynSection::kRods: return "RODS";
    case MoorDynSection::kPoints: return "POINTS";
    case MoorDynSection::kLines: return "LINES";
    case MoorDynSection::kOptions: return "OPTIONS";
    case MoorDynSection::kOutputs: return "OUTPUTS";
    case MoorDynSection::kEnd: return "need this line";
    case MoorDynSection::kOther: break;
  }
  return "(other)";
}

MoorDynLayout SplitMoorDynText(const std::string& text, const std::string& file) {
  const std::vector<std::string> lines = SplitLines(text);
  CheckNotEmpty(lines, file);
  MoorDynLayout layout;
  layout.last_line = static_cast<int>(lines.size());
  std::map<MoorDynSection, int> header_line;  // of each section read so far
  bool front_matter = true;  // until the first header MoorDyn knows
  int headers_to_skip = 0;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const int line = static_cast<int>(i + 1);
    const std::string body = StripComment(lines[i]);
    if (body.find("---") != std::string::npos) {
      const std::string phrase = Phrase(body);
      const MoorDynSection kind = SectionOf(phrase);
      if (front_matter && kind == MoorDynSection::kOther) continue;  // "-- MoorDyn Input File --"
      if (kind == MoorDynSection::kEnd) {
        WarnAfterEnd(lines, i, file, &layout.warnings);
        break;
      }
      front_matter = false;
      if (kind != MoorDynSection::kOther && header_line.count(kind))
        throw Error(At(file, line) + MoorDynSectionName(kind) + " given a second time (first at "
                    "line " + std::to_string(header_line[kind]) + "); expected each section once");
      header_line[kind] = line;
      layout.sections.push_back({kind, phrase, line, {}});
      headers_to_skip = HasColumnHeaders(kind) ? 2 : 0;
      continue;
    }
    if (front_matter) {
      if (layout.title.empty()) layout.title = Trim(lines[i]);
      continue;
    }
    if (headers_to_skip > 0) {  // whatever they hold, as MoorDyn does
      --headers_to_skip;
      continue;
    }
    std::vector<std::string> words = Words(body);
    if (!words.empty()) layout.sections.back().rows.push_back({line, std::move(words)});
  }
  WarnSkippedSections(layout, file, &layout.warnings);
  return layout;
}

}  // namespace cablefilm
