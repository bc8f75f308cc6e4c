#include "encode/jpeg_encoder.h"

#include <turbojpeg.h>

#include "core/error.h"

namespace cablefilm {

JpegEncoder::JpegEncoder(int quality) : handle_(tjInitCompress()), quality_(quality) {
  if (!handle_) throw Error(std::string("JPEG: cannot start TurboJPEG: ") + tjGetErrorStr2(nullptr));
  if (quality < 1 || quality > 100)
    throw Error("JPEG: quality must be 1..100, got " + std::to_string(quality));
}

JpegEncoder::~JpegEncoder() { tjDestroy(handle_); }

std::string JpegEncoder::Encode(const Image& image) {
  if (image.width <= 0 || image.height <= 0 ||
      image.rgba.size() != image.stride() * static_cast<std::size_t>(image.height))
    throw Error("JPEG: invalid image " + std::to_string(image.width) + "x" +
                std::to_string(image.height));
  unsigned char* out = nullptr;
  unsigned long size = 0;
  if (tjCompress2(handle_, image.rgba.data(), image.width, static_cast<int>(image.stride()),
                  image.height, TJPF_RGBA, &out, &size, TJSAMP_420, quality_,
                  TJFLAG_FASTDCT) != 0) {
    const std::string why = tjGetErrorStr2(handle_);
    tjFree(out);
    throw Error("JPEG: cannot encode a frame: " + why);
  }
  std::string bytes(reinterpret_cast<const char*>(out), size);
  tjFree(out);
  return bytes;
}

}  // namespace cablefilm
