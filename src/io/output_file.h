#pragma once
// A command's output named by its user (`convert -o`, `offset -o`). A regular file, or a new
// one, is written whole or not at all (atomic_file.h), beside the file a symbolic link names
// (/dev/stdout redirected to a file is that file); anything else that exists (a terminal, a
// pipe, /dev/null, /dev/full) cannot be renamed over and is written in place. Either way a
// failed write is an Error naming the path.
#include <string>

namespace cablefilm {

void WriteOutputFile(const std::string& path, const std::string& text);

}  // namespace cablefilm
