#include "app/open_files.h"

#include <sys/resource.h>

#include <string>

#include "core/error.h"
#include "run/max_tension_log.h"
#include "run/time_grid.h"
#include "scene/text_escape.h"

namespace cablefilm {
namespace {

struct OpenFiles {
  long per_line = 2;     // timeseries.csv, results.nc, the row maxima's temporary files
  long of_model = 0;     // points.csv and results.nc of several lines, body.csv
  long total = 0;
};

OpenFiles Count(const Model& model, long rows, int runs) {
  OpenFiles n;
  if (rows >= MaxTensionLog::kMemoryRows) n.per_line += runs;
  n.of_model = (model.lines.size() > 1 ? 2 : 0) + (model.bodies.empty() ? 0 : 1);
  n.total = static_cast<long>(model.lines.size()) * n.per_line + n.of_model + kOwnOpenFiles;
  return n;
}

std::string Lines(long n) { return std::to_string(n) + (n == 1 ? " line" : " lines"); }

}  // namespace

void CheckOpenFiles(const SceneDef& scene, const Model& model, int runs) {
  const TimeGrid grid = ChooseTimeGrid(model, scene.simulation, scene.output.interval);
  const OpenFiles n = Count(model, grid.outputs + 1, runs);
  rlimit limit{};
  if (::getrlimit(RLIMIT_NOFILE, &limit) != 0) return;  // no limit known: none to check
  const rlim_t needed = static_cast<rlim_t>(n.total);
  if (limit.rlim_cur == RLIM_INFINITY || limit.rlim_cur >= needed) return;
  if (limit.rlim_max == RLIM_INFINITY || limit.rlim_max >= needed) {
    rlimit raised = limit;
    raised.rlim_cur = limit.rlim_max;
    if (::setrlimit(RLIMIT_NOFILE, &raised) == 0) return;
  }
  const long lines = static_cast<long>(model.lines.size());
  const std::string from = " (from " + std::to_string(MaxTensionLog::kMemoryRows) + " rows)";
  std::string parts = std::to_string(n.per_line) + " a line: its timeseries.csv";
  if (n.per_line == 2) parts += " and results.nc";
  else if (runs == 1) parts += ", results.nc and the temporary file of its row maxima" + from;
  else parts += ", results.nc and the temporary files of its row maxima in both runs" + from;
  if (lines > 1) parts += "; the model's points.csv and results.nc";
  if (!model.bodies.empty()) parts += lines > 1 ? ", body.csv" : "; the model's body.csv";
  parts += "; " + std::to_string(kOwnOpenFiles) + " for the program itself";
  const long soft = static_cast<long>(limit.rlim_cur), hard = static_cast<long>(limit.rlim_max);
  const std::string limit_text =
      soft == hard ? "the limit on open files, " + std::to_string(hard) + " (ulimit -n)"
                   : "the limit on open files raised to its hard limit, " + std::to_string(hard) +
                         " (ulimit -Hn; ulimit -n is " + std::to_string(soft) + ")";
  const long fit = (hard - n.of_model - kOwnOpenFiles) / n.per_line;
  const std::string key = scene.from_moordyn                   ? "LINES"
                          : scene.lines.front().key == "cable" ? "cable"
                                                               : "line";
  throw Error(EscapeText(scene.path) + ": " + key + ": a run of its " + Lines(lines) + " keeps " +
              std::to_string(n.total) + " files open at once (" + parts + "), more than " +
              limit_text + "; expected " +
              (fit >= 1 ? "at most " + Lines(fit) + " under it"
                        : "a limit of at least " + std::to_string(n.total) + " files") +
              ": raise the limit (ulimit -n " + std::to_string(n.total) +
              "; beyond the hard limit as root) or run fewer lines");
}

}  // namespace cablefilm
