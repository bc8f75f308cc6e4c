#pragma once
// A CSV table of numbers under a header row that names its columns exactly (a sea's spectrum
// "omega,S", a recorded elevation "t,eta", a vessel's RAOs), read strictly as the motion
// tables are (table_file.h): every row as many finite decimals as the header has names, blank
// lines and lines starting with '#' skipped, at most kMaxTableBytes, kMaxTableRows rows and
// kMaxTableLineLength characters a line (scene_limits.h).
#include <string>
#include <vector>

namespace cablefilm {

// The rows of the file at `path`, each columns.size() numbers. `what` names the table in
// messages ("the spectrum table"), `units` the columns' units ("in rad/s and m^2 s/rad").
// Throws Error naming the file, the line and what was expected; also with fewer than
// `min_rows` rows.
std::vector<std::vector<double>> ReadNumberTable(const std::string& path,
                                                 const std::vector<std::string>& columns,
                                                 const std::string& what,
                                                 const std::string& units, int min_rows = 2);
// The same with any of several headers (`forms`): each row as many numbers as the one the
// file's header row is; `form` (if given) set to that header's index in `forms`.
std::vector<std::vector<double>> ReadNumberTableOfForms(
    const std::string& path, const std::vector<std::vector<std::string>>& forms,
    const std::string& what, const std::string& units, int min_rows = 2, int* form = nullptr);

}  // namespace cablefilm
