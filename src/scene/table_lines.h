#pragma once
// The lines of a CSV table read from a file, within the tables' limits (scene_limits.h:
// kMaxTableBytes, kMaxTableLineLength), checked while reading. Shared by the motion tables
// (table_file.h) and the tables of numbers (number_table.h), which parse the lines.
#include <functional>
#include <string>

namespace cablefilm {

// Calls take(line, number) for each line of `path` (its '\r' before '\n' removed; number counts
// from 1), the last line whether or not it ends in '\n'. Throws Error naming the file (and the
// line) when it is a directory, cannot be opened or read, is larger than kMaxTableBytes, or a
// line is longer than kMaxTableLineLength; `what` ("the motion table") and `expected` (what a
// row holds: "rows t,x,y ...") complete those messages. Errors thrown by `take` pass through.
void ReadTableLines(const std::string& path, const std::string& what, const std::string& expected,
                    const std::function<void(std::string&& line, long number)>& take);

// A line as a message may show it: escaped, and cut after 60 characters.
std::string ShownLine(const std::string& line);

}  // namespace cablefilm
