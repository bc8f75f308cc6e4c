#pragma once
// The film of a run: snapshots pushed by the simulation are drawn and encoded on a thread of
// their own, fed by a bounded queue (memory bounded whatever the film's length), into
// <out_dir>/film.mp4, optionally <out_dir>/frames/frame_000000.png ..., and at the end
// <out_dir>/max_tension.png. A film cut short (FinishPartial, or destroyed unfinished) stays as
// film.partial.mp4, which plays up to its last frame; no incomplete film takes the final name.
#include <memory>
#include <string>
#include <vector>

#include "view/frame_builder.h"
#include "view/history.h"
#include "view/scene_view.h"
#include "view/snapshot.h"

namespace cablefilm {

struct FilmOptions {
  int width = 1920, height = 1080;  // even
  double fps = 30;                  // frames per second of film
  int crf = 20;                     // x264 quality (lower = better, bigger)
  std::string preset = "veryfast";  // x264 speed preset
  std::string colormap = "viridis"; // viridis, cividis, magma, inferno, plasma
  bool write_film = true;           // film.mp4
  bool write_frames = false;        // frames/frame_000000.png ...
  std::string shader_dir;           // empty = $CABLEFILM_SHADERS, else the compiled-in dir
  std::string font_path;            // empty = DejaVu Sans through fontconfig
  // Added fields (defaults keep the behaviour above):
  bool write_max_tension = true;    // max_tension.png at Finish()
  std::string series_label = "elastic";  // legend of this run in max_tension.png
  int still_width = 1600, still_height = 900;  // size of max_tension.png
  int queue_capacity = 4;           // snapshots waiting to be drawn (Push blocks beyond)
  bool progress = true;             // progress line on stderr (only when it is a terminal)
  int png_compression = 1;          // zlib level of the frame PNGs (speed over size)
};

class FilmWriter {
 public:
  // Checks the options, the scene and the policy (the film's history: History), creates out_dir
  // (and frames/), starts the drawing thread and waits until its context, shaders, font and
  // encoder are ready: a bad option fails here. `total_frames` is only for the progress line
  // (0 = unknown).
  FilmWriter(const FilmOptions& options, const SceneView& scene, const FixedPolicy& policy,
             const std::string& out_dir, int total_frames);
  ~FilmWriter();  // if not finished: FinishPartial(), an error then printed on stderr
  FilmWriter(const FilmWriter&) = delete;
  FilmWriter& operator=(const FilmWriter&) = delete;

  // Queues a snapshot (times increasing); blocks while the queue is full. Rethrows an error of
  // the drawing thread (then nothing more is drawn).
  void Push(Snapshot snapshot);
  // Draws what is queued, flushes and closes film.mp4, writes max_tension.png. Idempotent;
  // rethrows an error of the drawing thread (the film is then not written).
  void Finish();
  // For a film cut short (Ctrl-C, a failure): draws what is queued and closes the film under
  // its partial name, film.partial.mp4, where it plays; max_tension.partial.png likewise.
  void FinishPartial();

  long frames_done() const;  // frames drawn so far
  // After Finish(): the film's time plot of the first line as its last frame shows it
  // (History: every output row the snapshots carried, else one sample a frame), labelled
  // options.series_label.
  MaxTensionSeries max_tension_series() const;
  // After Finish(): every line's series, each named by its label (the first's, when it has
  // none, by options.series_label; another's by LineName). These are also the curves of the
  // max_tension.png it writes.
  std::vector<MaxTensionSeries> all_max_tension_series() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace cablefilm
