#include "encode/tiled_jpeg.h"

#include <csetjmp>
#include <cstdio>
#include <algorithm>
#include <cstring>

#include <jpeglib.h>

#include "core/error.h"

namespace cablefilm {
namespace {

constexpr int kMcu = 16;  // 4:2:0: an MCU is 16x16 pixels

// libjpeg's errors end in a longjmp back to Compress (not an exception through C frames).
struct ErrorManager {
  jpeg_error_mgr pub;
  std::jmp_buf jump;
  char message[JMSG_LENGTH_MAX];
};

void ErrorExit(j_common_ptr cinfo) {
  auto* e = reinterpret_cast<ErrorManager*>(cinfo->err);
  (*cinfo->err->format_message)(cinfo, e->message);
  std::longjmp(e->jump, 1);
}

// The compressed bytes go to a growing vector, kept from one picture to the next.
struct Destination {
  jpeg_destination_mgr pub;
  std::vector<unsigned char>* bytes;
  std::size_t size = 0;  // written, once done
};

void InitDestination(j_compress_ptr cinfo) {
  auto* d = reinterpret_cast<Destination*>(cinfo->dest);
  if (d->bytes->size() < 65536) d->bytes->resize(65536);
  d->pub.next_output_byte = d->bytes->data();
  d->pub.free_in_buffer = d->bytes->size();
}

boolean EmptyOutputBuffer(j_compress_ptr cinfo) {
  auto* d = reinterpret_cast<Destination*>(cinfo->dest);
  const std::size_t used = d->bytes->size();  // libjpeg fills the whole buffer before asking
  d->bytes->resize(2 * used);
  d->pub.next_output_byte = d->bytes->data() + used;
  d->pub.free_in_buffer = d->bytes->size() - used;
  return TRUE;
}

void TermDestination(j_compress_ptr cinfo) {
  auto* d = reinterpret_cast<Destination*>(cinfo->dest);
  d->size = d->bytes->size() - d->pub.free_in_buffer;
}

// The largest number of MCUs up to 8 that divides a row's: a tile never spans two rows.
int TileMcus(int mcus_per_row) {
  for (int n = 8; n > 1; --n)
    if (mcus_per_row % n == 0) return n;
  return 1;
}

}  // namespace

TiledJpegEncoder::TiledJpegEncoder(int quality) : quality_(quality) {
  if (quality < 1 || quality > 100)
    throw Error("JPEG: quality must be 1..100, got " + std::to_string(quality));
}

void TiledJpegEncoder::Compress(const std::uint8_t* rgba, int width, int height,
                                std::size_t stride) {
  jpeg_compress_struct cinfo;
  ErrorManager err;
  Destination dest;
  dest.pub.init_destination = InitDestination;
  dest.pub.empty_output_buffer = EmptyOutputBuffer;
  dest.pub.term_destination = TermDestination;
  dest.bytes = &compressed_;
  cinfo.err = jpeg_std_error(&err.pub);
  err.pub.error_exit = ErrorExit;
  if (setjmp(err.jump)) {
    jpeg_destroy_compress(&cinfo);
    throw Error(std::string("JPEG: cannot encode a frame: ") + err.message);
  }
  jpeg_create_compress(&cinfo);
  cinfo.dest = &dest.pub;
  cinfo.image_width = static_cast<JDIMENSION>(width);
  cinfo.image_height = static_cast<JDIMENSION>(height);
  cinfo.input_components = 4;
  cinfo.in_color_space = JCS_EXT_RGBA;
  jpeg_set_defaults(&cinfo);  // YCbCr 4:2:0, standard Huffman tables
  jpeg_set_quality(&cinfo, quality_, TRUE);
  cinfo.dct_method = JDCT_IFAST;
  cinfo.restart_interval = static_cast<unsigned>(tile_w_ / kMcu);  // a marker after each tile
  jpeg_start_compress(&cinfo, TRUE);
  while (cinfo.next_scanline < cinfo.image_height) {
    JSAMPROW row = const_cast<JSAMPROW>(rgba + stride * cinfo.next_scanline);
    jpeg_write_scanlines(&cinfo, &row, 1);
  }
  jpeg_finish_compress(&cinfo);
  jpeg_destroy_compress(&cinfo);
  compressed_.resize(dest.size);
}

void TiledJpegEncoder::Split(const std::vector<int>& slots, bool header) {
  const unsigned char* p = compressed_.data();
  const std::size_t n = compressed_.size();
  // The markers up to the scan: each FFxx with a 2-byte length, up to SOS (FFDA).
  std::size_t i = 2;
  while (i + 4 <= n) {
    if (p[i] != 0xFF) throw Error("JPEG: unexpected bytes before the scan");
    const unsigned char marker = p[i + 1];
    i += 2 + ((p[i + 2] << 8) | p[i + 3]);
    if (marker == 0xDA) break;
  }
  if (header) header_.assign(reinterpret_cast<const char*>(p), i);
  std::size_t slot = 0, start = i;
  auto keep = [&](std::size_t end) {
    if (slot < slots.size() && slots[slot] >= 0)
      segments_[slots[slot]].assign(reinterpret_cast<const char*>(p) + start, end - start);
    ++slot;
  };
  for (; i + 1 < n; ++i) {
    if (p[i] != 0xFF || p[i + 1] == 0x00) continue;  // data, or a stuffed FF
    if (p[i + 1] >= 0xD0 && p[i + 1] <= 0xD7) {       // RSTn: the next tile
      keep(i);
      start = i + 2;
      ++i;
    } else if (p[i + 1] == 0xD9) {  // EOI
      keep(i);
      break;
    }
  }
  if (slot != slots.size()) throw Error("JPEG: the scan has not one segment per tile");
}

void TiledJpegEncoder::Reset(const Image& image) {
  width_ = image.width;
  height_ = image.height;
  tiled_ = width_ % kMcu == 0;
  tile_w_ = tiled_ ? kMcu * TileMcus(width_ / kMcu) : 0;
  columns_ = tiled_ ? width_ / tile_w_ : 0;
  rows_ = (height_ + kMcu - 1) / kMcu;
  segments_.assign(tiled_ ? static_cast<std::size_t>(columns_) * rows_ : 0, std::string());
  kept_ = false;
}

void TiledJpegEncoder::Encode(const Image& image, std::string* out,
                              const std::vector<ImageRect>* changed) {
  if (image.width <= 0 || image.height <= 0 ||
      image.rgba.size() != image.stride() * static_cast<std::size_t>(image.height))
    throw Error("JPEG: invalid image " + std::to_string(image.width) + "x" +
                std::to_string(image.height));
  if (image.width != width_ || image.height != height_) Reset(image);
  reencoded_ = 1;
  if (!tiled_) {
    Compress(image.rgba.data(), width_, height_, image.stride());
    out->append(reinterpret_cast<const char*>(compressed_.data()), compressed_.size());
    return;
  }
  const std::size_t tiles = segments_.size();
  const std::size_t stride = image.stride(), tile_bytes = static_cast<std::size_t>(tile_w_) * 4;
  dirty_.clear();
  reached_.assign(tiles, changed ? 0 : 1);
  if (changed)
    for (const ImageRect& b : *changed) {
      const int x0 = std::max(b.x0, 0), y0 = std::max(b.y0, 0);
      const int x1 = std::min(b.x1, width_), y1 = std::min(b.y1, height_);
      for (int r = y0 / kMcu; y1 > y0 && x1 > x0 && r <= (y1 - 1) / kMcu; ++r)
        for (int c = x0 / tile_w_; c <= (x1 - 1) / tile_w_; ++c) reached_[r * columns_ + c] = 1;
    }
  const bool kept = kept_;
  kept_ = false;  // until this picture is done (an error leaves the tiles unknown)
  if (kept) {  // the tiles whose pixels differ from the last picture's
    for (int r = 0; r < rows_; ++r) {
      const int y0 = r * kMcu, y1 = std::min(y0 + kMcu, height_);
      for (int c = 0; c < columns_; ++c) {
        if (!reached_[r * columns_ + c]) continue;
        const std::size_t x = c * tile_bytes;
        for (int y = y0; y < y1; ++y)
          if (std::memcmp(image.row(y) + x, previous_.row(y) + x, tile_bytes) != 0) {
            dirty_.push_back(r * columns_ + c);
            break;
          }
      }
    }
  }
  if (!kept || dirty_.size() * 4 > tiles * 3) {
    // The first picture, or most of it changed: the whole picture, every tile kept.
    Compress(image.rgba.data(), width_, height_, stride);
    slots_.resize(tiles);
    for (std::size_t t = 0; t < tiles; ++t) slots_[t] = static_cast<int>(t);
    Split(slots_, true);
    previous_.width = width_;
    previous_.height = height_;
    previous_.rgba = image.rgba;  // storage reused once sized
  } else {
    reencoded_ = static_cast<double>(dirty_.size()) / tiles;
    // The changed tiles of whole MCU rows side by side, `columns_` to a row of the patch, then
    // those of a short last row (its own patch: a tile's bottom edge is padded as in the whole
    // picture only at the picture's bottom).
    const int last_h = height_ - (rows_ - 1) * kMcu;
    std::size_t k = 0;
    for (int pass = 0; pass < 2; ++pass) {
      const bool short_row = pass == 1;
      if (short_row && last_h == kMcu) break;
      const std::size_t begin = k;
      while (k < dirty_.size() && (short_row || last_h == kMcu || dirty_[k] / columns_ < rows_ - 1))
        ++k;
      const std::size_t count = k - begin;
      if (count == 0) continue;
      const int per_row = static_cast<int>(std::min<std::size_t>(count, columns_));
      const int patch_rows = static_cast<int>((count + per_row - 1) / per_row);
      const int tile_h = short_row ? last_h : kMcu;
      const std::size_t patch_stride = per_row * tile_bytes;
      patch_.assign(patch_stride * tile_h * patch_rows, 0);
      slots_.assign(static_cast<std::size_t>(per_row) * patch_rows, -1);
      for (std::size_t j = 0; j < count; ++j) {
        const int tile = dirty_[begin + j];
        const int r = tile / columns_, c = tile % columns_;
        const std::size_t x = c * tile_bytes;
        const int pr = static_cast<int>(j) / per_row, pc = static_cast<int>(j) % per_row;
        for (int y = 0; y < tile_h; ++y) {
          const std::uint8_t* src = image.row(r * kMcu + y) + x;
          std::memcpy(patch_.data() + (pr * tile_h + y) * patch_stride + pc * tile_bytes, src, tile_bytes);
          std::memcpy(previous_.row(r * kMcu + y) + x, src, tile_bytes);
        }
        slots_[j] = tile;
      }
      Compress(patch_.data(), per_row * tile_w_, tile_h * patch_rows, patch_stride);
      Split(slots_, false);
    }
  }
  kept_ = true;
  // The file: the header, then each tile's bytes with RST0..RST7 in turn between them, EOI.
  out->append(header_);
  for (std::size_t t = 0; t < tiles; ++t) {
    out->append(segments_[t]);
    if (t + 1 < tiles) {
      out->push_back(static_cast<char>(0xFF));
      out->push_back(static_cast<char>(0xD0 + t % 8));
    }
  }
  out->push_back(static_cast<char>(0xFF));
  out->push_back(static_cast<char>(0xD9));
}

}  // namespace cablefilm
