#pragma once
// The film: a second, deterministic pass over the simulation that pushes a snapshot every
// film frame to the renderer, so the colour range and the world box found by the first pass
// hold for every frame while memory stays bounded whatever the film's length.
#include <Eigen/Core>
#include <atomic>
#include <string>
#include <vector>

#include "app/run_extent.h"
#include "app/simulation_run.h"
#include "scene/scene_def.h"

namespace cablefilm {

struct FilmRequest {
  std::string out_dir;
  bool film = true;             // film.mp4 (false: max_tension.png only)
  bool frames = false;          // frames/frame_000000.png ...
  int width = 1920, height = 1080;
  double fps = 30, speed = 1;   // film frames per second; simulated seconds per film second
  int crf = 20;
  std::string colormap = "viridis";
  double tension_min = -1, tension_max = -1;  // [N]; negative: from the runs
  std::string shader_dir;
};

// A model already simulated once (its first pass gave the extent).
struct FilmRun {
  std::string label;            // "elastic", "inextensible"
  const CableModel* model;
  TimeGrid grid;
  CableState initial;
  Eigen::VectorXd initial_tension;  // [N]
  RunExtent extent;
};

// Renders film.mp4 of the first run, with the second (if any) drawn over it on the same
// colour range, and max_tension.png with every run (the paper's Figure 1). Returns false if `stop` was raised (the film is then
// closed at the last frame drawn). Throws Error.
bool RenderFilm(const SceneDef& scene, const std::vector<FilmRun>& runs,
                const FilmRequest& request, const std::atomic<int>& stop);

}  // namespace cablefilm
