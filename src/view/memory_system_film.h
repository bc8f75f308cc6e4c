#pragma once
// A frame of a system's run held in memory (run/memory_system_run.h), drawn as the system's
// film (system_film.h) draws it: every line at that row, the time plot and the envelope of
// every row up to it, on the colour range and world box of the whole run.
#include "encode/image.h"
#include "run/memory_system_run.h"
#include "view/film_pass.h"

namespace cablefilm {

// The frame at output row `row` (0 to rows - 1), request.width x request.height. Throws Error.
Image DrawMemorySystemFrame(const MemorySystemRun& run, long row, const FilmRequest& request);

}  // namespace cablefilm
