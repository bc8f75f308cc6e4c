#pragma once
// PNG files through libpng: 8-bit RGBA, written whole or not at all (cablefilm::AtomicFile).
#include <memory>
#include <string>

#include "encode/image.h"

namespace cablefilm {

// zlib level 0..9: 1 is ~4x faster than the default 6 for rendered frames at ~15 % more bytes.
struct PngOptions {
  int compression_level = 6;
  bool keep_alpha = false;  // false: write RGB (frames are opaque), true: write RGBA
  // Only the "up" row filter instead of libpng's trial of all five per row: on a flat figure
  // (max_tension.png, level 4) as small a file in 40 % of the time.
  bool up_filter_only = false;
  int memory_level = 8;  // zlib's memLevel 1..9 (its hash table and block size), 8 its default
};

// Writes `image` to `path` (a temporary file renamed on success). Throws Error with the path.
void WritePng(const std::string& path, const Image& image, const PngOptions& options = {});

// A PNG written a band of rows at a time, for a picture drawn in bands and never held whole
// (view/flat_raster.h); written whole or not at all as WritePng. Throws Error with the path.
class PngRowWriter {
 public:
  PngRowWriter(const std::string& path, int width, int height, const PngOptions& options = {});
  ~PngRowWriter();  // uncommitted: the temporary file removed
  PngRowWriter(const PngRowWriter&) = delete;
  PngRowWriter& operator=(const PngRowWriter&) = delete;

  void Write(const Image& band);  // the next band.height rows, as wide as the picture
  void Commit();                  // after the last row

 private:
  struct State;
  std::unique_ptr<State> state_;
};

// The PNG file's bytes, in memory (a snapshot served over HTTP). Throws Error.
std::string EncodePng(const Image& image, const PngOptions& options = {});

// Reads any 8-bit or 16-bit PNG (grey, RGB, with or without alpha, palette) as RGBA8.
// Throws Error with the path. Used by tests and the golden-image comparison.
Image ReadPng(const std::string& path);

}  // namespace cablefilm
