#include "scene/moordyn_file.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "core/error.h"
#include "scene/input_file.h"
#include "scene/moordyn_checks.h"
#include "scene/moordyn_layout.h"
#include "scene/moordyn_options.h"
#include "scene/moordyn_row.h"
#include "scene/moordyn_rows.h"
#include "scene/scene_limits.h"
#include "scene/text_escape.h"

namespace cablefilm {
namespace {

std::string ReadText(const std::string& path) {
  return ReadInputFile(path, "MoorDyn input file", "a MoorDyn input file");
}

std::string At(const std::string& file, int line) {
  return file + ":" + std::to_string(line) + ": ";
}

// Each row of a table section as a MoorDynRow; columns beyond the last named are not read.
template <typename Read>
void ForEachRow(const MoorDynSectionText& section, const std::string& file,
                const std::vector<std::string>& columns, std::size_t required,
                std::vector<std::string>* warnings, Read read) {
  for (std::size_t i = 0; i < section.rows.size(); ++i) {
    const MoorDynRow row(file, MoorDynSectionName(section.kind), static_cast<int>(i + 1),
                         section.rows[i], columns, required);
    if (row.size() > columns.size())
      warnings->push_back(row.Note("the columns after " + columns.back() + " are not read"));
    read(row, static_cast<int>(i + 1));
  }
}

void ReadLineTypes(const MoorDynSectionText& s, const std::string& file, MoorDynSystem* sys) {
  std::unordered_map<std::string, int> lines;  // each name's line of the file
  ForEachRow(s, file, kMoorDynLineTypeColumns, 10, &sys->warnings,
             [&](const MoorDynRow& row, int) {
               MoorDynLineType type = ReadMoorDynLineType(row);
               const auto [other, added] = lines.emplace(type.name, type.line);
               if (!added)
                 row.Refuse(0, QuoteText(type.name) + " is already the name of the line type "
                                 "at line " + std::to_string(other->second) +
                                 "; expected a name of its own");
               sys->line_types.push_back(std::move(type));
             });
}

void ReadPoints(const MoorDynSectionText& s, const std::string& file, MoorDynSystem* sys) {
  for (std::size_t i = 0; i < s.rows.size(); ++i) {
    const bool forces = s.rows[i].words.size() >= kMoorDynPointForceColumns.size();
    const auto& columns = forces ? kMoorDynPointForceColumns : kMoorDynPointColumns;
    const MoorDynRow row(file, "POINTS", static_cast<int>(i + 1), s.rows[i], columns,
                         columns.size());
    if (row.size() > columns.size())
      sys->warnings.push_back(row.Note("the columns after Ca are not read"));
    sys->points.push_back(ReadMoorDynPoint(row, static_cast<int>(i + 1), &sys->warnings));
  }
}

// "value name [description]"; the value is kept as text, checked when cablefilm uses it.
void ReadOptions(const MoorDynSectionText& s, const std::string& file, MoorDynSystem* sys) {
  for (const MoorDynRowText& row : s.rows) {
    if (row.words.size() < 2) {
      sys->warnings.push_back(At(file, row.line) + "OPTIONS: " + QuoteText(row.words[0]) +
                              " not read: an option is a value followed by its name");
      continue;
    }
    const std::string& name = row.words[1];
    const auto before = sys->options.find(name);
    if (before != sys->options.end())
      sys->warnings.push_back(At(file, row.line) + "OPTIONS " + EscapeText(name) +
                              " given again (first at line " +
                              std::to_string(before->second.line) + "): the last value is used");
    const MoorDynOption option{row.line, row.words[0]};
    CheckMoorDynOption(file, name, option);
    sys->options[name] = option;
  }
}

void ReadSection(const MoorDynSectionText& s, const std::string& file, MoorDynSystem* sys) {
  switch (s.kind) {
    case MoorDynSection::kLineTypes: ReadLineTypes(s, file, sys); break;
    case MoorDynSection::kBodies:
      ForEachRow(s, file, kMoorDynBodyColumns, 14, &sys->warnings,
                 [&](const MoorDynRow& row, int id) {
                   sys->bodies.push_back(ReadMoorDynBody(row, id));
                 });
      break;
    case MoorDynSection::kPoints: ReadPoints(s, file, sys); break;
    case MoorDynSection::kLines:
      ForEachRow(s, file, kMoorDynLineColumns, 7, &sys->warnings,
                 [&](const MoorDynRow& row, int id) {
                   sys->lines.push_back(ReadMoorDynLine(row, id));
                 });
      break;
    case MoorDynSection::kOptions: ReadOptions(s, file, sys); break;
    case MoorDynSection::kRods:
      if (!s.rows.empty())
        throw Error(At(file, s.rows[0].line) + "RODS row 1: rods are not supported yet; "
                    "expected no rows under RODS");
      break;
    case MoorDynSection::kRodTypes:
      if (!s.rows.empty())
        sys->warnings.push_back(At(file, s.line) + "ROD TYPES not read (rods are not "
                                "supported yet)");
      break;
    case MoorDynSection::kOutputs:
      if (!s.rows.empty())
        sys->warnings.push_back(At(file, s.line) + "OUTPUTS not read: cablefilm writes its own "
                                "results (each line's tensions and positions)");
      break;
    case MoorDynSection::kEnd:
    case MoorDynSection::kOther: break;
  }
}

// MoorDyn needs at least one line (its documentation: "MoorDyn requires at least one line").
void CheckHasLines(const MoorDynLayout& layout, const std::string& file) {
  for (const MoorDynSectionText& s : layout.sections)
    if (s.kind == MoorDynSection::kLines) {
      if (s.rows.empty())
        throw Error(At(file, s.line) + "LINES has no rows; expected at least one line");
      return;
    }
  throw Error(At(file, layout.last_line) + "no LINES section; expected a header "
              "\"---- LINES ----\", two lines of column names and units, and a row per line");
}

}  // namespace

MoorDynSystem ReadMoorDynText(const std::string& text, const std::string& file) {
  const std::string name = EscapeText(file);
  const MoorDynLayout layout = SplitMoorDynText(text, name);
  MoorDynSystem system;
  system.file = file;
  system.last_line = layout.last_line;
  system.title = layout.title;
  system.warnings = layout.warnings;
  for (const MoorDynSectionText& section : layout.sections) ReadSection(section, name, &system);
  CheckHasLines(layout, name);
  CheckMoorDynReferences(name, &system);
  return system;
}

std::unordered_map<std::string, std::size_t> MoorDynLineTypeIndex(const MoorDynSystem& system) {
  std::unordered_map<std::string, std::size_t> index;
  for (std::size_t i = 0; i < system.line_types.size(); ++i)
    index.emplace(system.line_types[i].name, i);
  return index;
}

MoorDynSystem ReadMoorDynFile(const std::string& path) {
  return ReadMoorDynText(ReadText(path), path);
}

}  // namespace cablefilm
