#pragma once
// The files a run keeps open at once, against the process's limit on open files (RLIMIT_NOFILE,
// `ulimit -n`): `check` and `run` refuse alike, before anything is written, a model whose run
// would fail midway with "Too many open files"; the soft limit is raised to the hard one when
// that is enough.
#include "core/model.h"
#include "scene/scene_def.h"

namespace cablefilm {

// What the program holds open beside a run's files: its standard streams, the output folder's
// lock and ledger, a module or a temporary file being opened, the film's encoder (9 counted
// while a run of 400 lines wrote its files).
constexpr long kOwnOpenFiles = 32;

// Throws Error naming the scene file and its lines when the files a run of `model` keeps open
// at once exceed the limit on open files, even raised to the hard limit (to which it is raised
// when that is enough). Counted: each line's timeseries.csv and results.nc, and from
// MaxTensionLog::kMemoryRows rows each of `runs` runs' row maxima of the line (compare keeps the
// first run's while the second runs); with several lines points.csv and the model's results.nc;
// with bodies body.csv; kOwnOpenFiles.
void CheckOpenFiles(const SceneDef& scene, const Model& model, int runs = 1);

}  // namespace cablefilm
