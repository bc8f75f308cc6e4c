#pragma once
// What the command line asks of a run, and what a run reports back (for the tests).
#include <limits>
#include <string>

#include "app/command.h"
#include "run/run_summary.h"
#include "scene/film_settings.h"
#include "view/film_pass.h"

namespace cablefilm {

// What the command line says of a run: the film's settings over the scene's, and where it goes.
struct RunOptions : FilmOverrides {
  std::string out_dir;          // empty: output/<scene name>
  int film = -1;                // -1: as the scene says, 0: no film, 1: film
  std::string shader_dir;       // empty: CABLEFILM_SHADERS or the built-in path
};

// The film and output options of run and compare (and sweep, for each case) into `o`.
void AddRunOptions(CLI::App* cmd, RunOptions* o,
                   const std::string& out_help = "output folder (default output/<scene name>)");

// What a run reports and what its pictures show (for the tests; NaN: not made). All come from
// the same output rows, so the peaks agree: the film's to the last bit, the CSV's to its 10
// significant digits.
struct RunReport {
  RunSummary summary;     // the run's: its rows and the peak it printed
  PictureReport figure;   // max_tension[.partial].png
  PictureReport film;     // the film's time plot at its last frame
};

}  // namespace cablefilm
