#include "view/max_tension_figure.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "core/error.h"
#include "encode/png_writer.h"
#include "scene/text_escape.h"
#include "view/flat_raster.h"
#include "view/text.h"
#include "view/time_trace.h"

namespace cablefilm {

void WriteMaxTensionPng(const std::string& path, const std::vector<MaxTensionSeries>& series,
                        int width, int height, const std::string& title,
                        const std::string& font_path) {
  const Frame frame = MakeMaxTensionFigure(title, series, width, height);
  FontAtlas font(font_path);
  const FlatFrameRaster raster(frame, &font);
  // Every run writes it: the "up" filter at level 3 (zlib's fast match) takes 11.9 ms of CPU
  // against 17.4 ms at level 4 and 20 ms at level 6 with the same filter (case P63, 1600x900),
  // for a file 22 % larger (119 against 97 kB); every filter tried costs twice that again. And
  // zlib's memLevel 5 rather than 8: a hash table an eighth the size, slid every 32 kB of the
  // 4.3 MB of rows, and blocks of 2k symbols: 19 % fewer instructions deflating (87 against
  // 108 M) for a file no larger (117.9 against 118.2 kB), the same rows in it.
  PngOptions png;
  png.compression_level = 3;
  png.up_filter_only = true;
  png.memory_level = 5;
  // Drawn and written 128 rows at a time (800 kB at 1600 px), each band deflated while its
  // pixels are still in the cache, rather than 5.8 MB drawn first, every page of it faulted in.
  constexpr int kBandRows = 128;
  PngRowWriter writer(path, width, height, png);
  Image band;
  for (int y0 = 0; y0 < height; y0 += kBandRows) {
    const int rows = std::min(kBandRows, height - y0);
    if (band.height != rows) band = Image(width, rows);
    raster.DrawRows(y0, &band);
    writer.Write(band);
  }
  writer.Commit();
}

void FindPeak(const std::vector<double>& t, const std::vector<double>& v, PictureReport* r) {
  for (std::size_t i = 0; i < t.size() && i < v.size(); ++i)
    if (std::isfinite(v[i]) && !(v[i] <= r->peak)) {
      r->peak = v[i];
      r->peak_t = t[i];
    }
}

PictureReport WriteMaxTensionFigure(const SceneDef& scene, const std::vector<RowMaxima>& rows,
                                    const std::string& out_dir, bool complete,
                                    const std::string& what) {
  const std::string name = complete ? "max_tension.png" : "max_tension.partial.png";
  // The time axis spans the rows of every series (all have the same output times).
  double t_end = 0;
  for (const RowMaxima& r : rows) {
    MaxTensionLog::Cursor c(*r.rows);
    double t, v;
    while (c.Next(std::numeric_limits<double>::infinity(), &t, &v)) t_end = std::max(t_end, t);
  }
  std::vector<MaxTensionSeries> series;
  PictureReport report;
  std::string peak_label;
  for (const RowMaxima& r : rows) {
    ThinnedTrace trace(1, t_end > 0 ? t_end / 8192 : 0);
    MaxTensionLog::Cursor c(*r.rows);
    double t, v;
    while (c.Next(std::numeric_limits<double>::infinity(), &t, &v)) trace.Add(t, v);
    series.push_back({r.label, trace.times(), trace.values(), r.breaking_load});
    const double before = report.peak;
    FindPeak(trace.times(), trace.values(), &report);
    if (!(report.peak == before)) peak_label = r.label;
  }
  std::string title = "Maximum tension along " + what + ": " + scene.title;
  if (!complete) title += " (cut short)";
  try {
    WriteMaxTensionPng(out_dir + "/" + name, series, 1600, 900, title);
  } catch (const Error& e) {
    throw Error(name + " could not be drawn: " + e.what());
  }
  std::printf("wrote %s/%s (maximum tension of every output row: peak %.6g N at t = %.4g s%s)\n",
              EscapeText(out_dir).c_str(), name.c_str(), report.peak, report.peak_t,
              rows.size() > 1 ? (", " + EscapeText(peak_label)).c_str() : "");
  return report;
}

PictureReport WriteMaxTensionFigure(const SceneDef& scene, const std::vector<const Run*>& runs,
                                    const std::string& out_dir, bool complete) {
  std::vector<RowMaxima> rows;
  bool several = false;  // lines: a curve a line, named by it
  for (const Run* run : runs) {
    const Model& m = run->model;
    several = several || m.lines.size() > 1;
    for (std::size_t i = 0; i < m.lines.size(); ++i) {
      std::string label = run->label;
      if (m.lines.size() > 1)
        label = runs.size() > 1 ? m.line_names[i] + " (" + run->label + ")" : m.line_names[i];
      rows.push_back({label, &run->lines[i].row_max,
                      SingleBreakingLoad(m.lines[i].line.breaking_load)});
    }
  }
  return WriteMaxTensionFigure(scene, rows, out_dir, complete, several ? "each line" : "the cable");
}

}  // namespace cablefilm
