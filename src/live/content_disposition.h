#pragma once
// The Content-Disposition header of a download named after user data (the scene file's stem):
// RFC 6266, the name as RFC 5987's percent-encoded UTF-8 (filename*) after an ASCII fallback
// (filename) for clients without it. Neither part can hold a control character, a quote or a
// backslash, whatever the name holds: the header cannot be broken or followed by another.
#include <string>

namespace cablefilm {

// The whole header line, "Content-Disposition: attachment; filename=\"...\";
// filename*=UTF-8''...\r\n". In the fallback every character but printable ASCII, and `"`, `\`
// and `%` (which some clients decode), is "_"; bytes that are not UTF-8 are "_" in both.
std::string ContentDisposition(const std::string& filename);

}  // namespace cablefilm
