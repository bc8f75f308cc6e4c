#pragma once
// max_tension.png, the paper's Figure 1 as a still: the largest tension along each line at
// every output row against time, drawn on the CPU (flat_raster.h) in the light theme, so that
// a run writes it without a GL context or a shader compiler.
#include <limits>
#include <string>
#include <vector>

#include "run/max_tension_log.h"
#include "run/run.h"
#include "scene/scene_def.h"
#include "view/film_pass.h"
#include "view/frame_builder.h"

namespace cablefilm {

// Every series on one pair of axes, written whole or not at all. Throws Error.
void WriteMaxTensionPng(const std::string& path, const std::vector<MaxTensionSeries>& series,
                        int width = 1600, int height = 900,
                        const std::string& title = "Maximum tension along the cable",
                        const std::string& font_path = "");

// Raises r's peak (and its time) to the largest finite value of a series, if larger.
void FindPeak(const std::vector<double>& t, const std::vector<double>& v, PictureReport* r);

// One series of max_tension.png: its name and its rows' largest tensions (the run's or a
// system's line's record, borrowed).
struct RowMaxima {
  std::string label;
  const MaxTensionLog* rows = nullptr;
  double breaking_load = std::numeric_limits<double>::quiet_NaN();  // the line's one MBL [N]
};

// <out_dir>/max_tension.png, or max_tension.partial.png when the rows are those of a run cut
// short (`complete` false): every series on one pair of axes, thinned to the extremes of each
// 1/8192 of the time axis (ThinnedTrace), so that the largest value drawn is the rows' peak
// (reported, with the series holding it when there are several). `what` is what the title
// names, e.g. "the cable". Throws Error when it cannot be drawn, saying so.
PictureReport WriteMaxTensionFigure(const SceneDef& scene, const std::vector<RowMaxima>& series,
                                    const std::string& out_dir, bool complete,
                                    const std::string& what);

// The same for runs (their row maxima: a curve a line, named by the run's label for a model of
// one line, else by the line's name).
PictureReport WriteMaxTensionFigure(const SceneDef& scene, const std::vector<const Run*>& runs,
                                    const std::string& out_dir, bool complete);

}  // namespace cablefilm
