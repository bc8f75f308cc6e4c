#include "encode/png_writer.h"

#include <png.h>

#include <csetjmp>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "core/error.h"
#include "io/atomic_file.h"

namespace cablefilm {
namespace {

// libpng reports errors by longjmp; these C-style helpers keep only trivially destructible
// objects between setjmp and the calls that may jump, so no C++ destructor is skipped.
struct PngErrorSink {
  char message[256];
};

void OnPngError(png_structp png, png_const_charp msg) {
  auto* sink = static_cast<PngErrorSink*>(png_get_error_ptr(png));
  std::snprintf(sink->message, sizeof sink->message, "%s", msg);
  png_longjmp(png, 1);
}
void OnPngWarning(png_structp, png_const_charp) {}

// A stream's header (StartPng), its rows (WritePngRows, any number of times) and its end
// (EndPng); each destroys the stream and returns false on an error, its message in the sink.
bool StartPng(std::FILE* file, int width, int height, const PngOptions& options,
              png_structp* png_out, png_infop* info_out, PngErrorSink* sink) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, sink, OnPngError, OnPngWarning);
  if (!png) {
    std::snprintf(sink->message, sizeof sink->message, "out of memory");
    return false;
  }
  png_infop info = png_create_info_struct(png);
  if (!info || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  png_init_io(png, file);
  png_set_compression_level(png, options.compression_level);
  png_set_compression_mem_level(png, options.memory_level);
  if (options.up_filter_only) png_set_filter(png, 0, PNG_FILTER_UP);
  png_set_IHDR(png, info, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height), 8,
               options.keep_alpha ? PNG_COLOR_TYPE_RGBA : PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_sRGB(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
  png_write_info(png, info);
  if (!options.keep_alpha) png_set_filler(png, 0, PNG_FILLER_AFTER);  // drop the 4th byte
  *png_out = png;
  *info_out = info;
  return true;
}

bool WritePngRows(png_structp png, png_infop info, const png_bytep* rows, int n) {
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  png_write_rows(png, const_cast<png_bytepp>(rows), static_cast<png_uint_32>(n));
  return true;
}

bool EndPng(png_structp png, png_infop info) {
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return true;
}

bool WritePngStream(std::FILE* file, const Image& image, const PngOptions& options,
                    const png_bytep* rows, PngErrorSink* sink) {
  png_structp png = nullptr;
  png_infop info = nullptr;
  return StartPng(file, image.width, image.height, options, &png, &info, sink) &&
         WritePngRows(png, info, rows, image.height) && EndPng(png, info);
}

struct ReadResult {
  png_uint_32 width, height;
};

bool ReadPngHeader(std::FILE* file, png_structp* png_out, png_infop* info_out, ReadResult* out,
                   PngErrorSink* sink) {
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, sink, OnPngError, OnPngWarning);
  if (!png) {
    std::snprintf(sink->message, sizeof sink->message, "out of memory");
    return false;
  }
  png_infop info = png_create_info_struct(png);
  if (!info || setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, &info, nullptr);
    return false;
  }
  png_init_io(png, file);
  png_read_info(png, info);
  png_set_expand(png);          // palette / low-bit grey / tRNS -> 8-bit channels + alpha
  png_set_strip_16(png);        // 16 -> 8 bits
  png_set_gray_to_rgb(png);
  png_set_filler(png, 0xff, PNG_FILLER_AFTER);  // RGB -> RGBA
  png_read_update_info(png, info);
  out->width = png_get_image_width(png, info);
  out->height = png_get_image_height(png, info);
  *png_out = png;
  *info_out = info;
  return true;
}

bool ReadPngRows(png_structp png, png_infop info, png_bytepp rows, PngErrorSink* sink) {
  (void)sink;
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, &info, nullptr);
    return false;
  }
  png_read_image(png, rows);
  png_read_end(png, nullptr);
  png_destroy_read_struct(&png, &info, nullptr);
  return true;
}

std::vector<png_bytep> ImageRows(const std::string& what, const Image& image) {
  if (image.width <= 0 || image.height <= 0 ||
      image.rgba.size() != image.stride() * static_cast<std::size_t>(image.height))
    throw Error("cannot write " + what + ": invalid image " + std::to_string(image.width) + "x" +
                std::to_string(image.height));
  std::vector<png_bytep> rows(static_cast<std::size_t>(image.height));
  for (int y = 0; y < image.height; ++y) rows[y] = const_cast<png_bytep>(image.row(y));
  return rows;
}

}  // namespace

std::string EncodePng(const Image& image, const PngOptions& options) {
  const std::vector<png_bytep> rows = ImageRows("a PNG in memory", image);
  char* buffer = nullptr;
  std::size_t size = 0;
  std::FILE* stream = open_memstream(&buffer, &size);
  if (!stream) throw Error("cannot encode a PNG in memory: " + std::string(std::strerror(errno)));
  PngErrorSink sink{};
  const bool ok = WritePngStream(stream, image, options, rows.data(), &sink);
  std::fclose(stream);  // sets buffer and size
  std::string bytes(buffer ? buffer : "", buffer ? size : 0);
  std::free(buffer);
  if (!ok) throw Error(std::string("cannot encode a PNG in memory: ") + sink.message);
  return bytes;
}

void WritePng(const std::string& path, const Image& image, const PngOptions& options) {
  const std::vector<png_bytep> rows = ImageRows(path, image);
  AtomicFile file(path);
  PngErrorSink sink{};
  if (!WritePngStream(file.stream(), image, options, rows.data(), &sink))
    throw Error("cannot write PNG " + path + ": " + sink.message);
  file.Commit();
}

struct PngRowWriter::State {
  AtomicFile file;
  PngErrorSink sink{};
  png_structp png = nullptr;  // null once destroyed (ended, or after an error)
  png_infop info = nullptr;
  int width = 0, rows_left = 0;
  explicit State(const std::string& path) : file(path) {}
};

PngRowWriter::PngRowWriter(const std::string& path, int width, int height,
                           const PngOptions& options)
    : state_(std::make_unique<State>(path)) {
  State& s = *state_;
  if (width <= 0 || height <= 0)
    throw Error("cannot write " + path + ": invalid image " + std::to_string(width) + "x" +
                std::to_string(height));
  s.width = width;
  s.rows_left = height;
  if (!StartPng(s.file.stream(), width, height, options, &s.png, &s.info, &s.sink))
    throw Error("cannot write PNG " + path + ": " + s.sink.message);
}

PngRowWriter::~PngRowWriter() {
  if (state_->png) png_destroy_write_struct(&state_->png, &state_->info);
}

void PngRowWriter::Write(const Image& band) {
  State& s = *state_;
  const std::string& path = s.file.path();
  if (!s.png) throw Error("cannot write PNG " + path + ": " + s.sink.message);
  if (band.width != s.width || band.height > s.rows_left)
    throw Error("cannot write PNG " + path + ": a band of " + std::to_string(band.width) + "x" +
                std::to_string(band.height) + " does not fit");
  const std::vector<png_bytep> rows = ImageRows(path, band);
  s.rows_left -= band.height;
  if (!WritePngRows(s.png, s.info, rows.data(), band.height)) {
    s.png = nullptr;
    throw Error("cannot write PNG " + path + ": " + s.sink.message);
  }
}

void PngRowWriter::Commit() {
  State& s = *state_;
  const std::string& path = s.file.path();
  if (!s.png || s.rows_left != 0)
    throw Error("cannot write PNG " + path + ": " +
                (s.png ? std::to_string(s.rows_left) + " rows missing" : s.sink.message));
  const bool ended = EndPng(s.png, s.info);
  s.png = nullptr;
  if (!ended) throw Error("cannot write PNG " + path + ": " + s.sink.message);
  s.file.Commit();
}

Image ReadPng(const std::string& path) {
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (!file) throw Error("cannot open PNG " + path + ": " + std::strerror(errno));
  png_structp png = nullptr;
  png_infop info = nullptr;
  ReadResult header{};
  PngErrorSink sink{};
  if (!ReadPngHeader(file, &png, &info, &header, &sink)) {
    std::fclose(file);
    throw Error("cannot read PNG " + path + ": " + sink.message);
  }
  Image image(static_cast<int>(header.width), static_cast<int>(header.height));
  std::vector<png_bytep> rows(header.height);
  for (png_uint_32 y = 0; y < header.height; ++y) rows[y] = image.row(static_cast<int>(y));
  const bool ok = ReadPngRows(png, info, rows.data(), &sink);
  std::fclose(file);
  if (!ok) throw Error("cannot read PNG " + path + ": " + sink.message);
  return image;
}

}  // namespace cablefilm
