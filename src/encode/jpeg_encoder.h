#pragma once
// JPEG through TurboJPEG: each live frame is encoded once and the same bytes go to every
// viewer. One encoder per thread (a TurboJPEG handle is not thread-safe).
#include <string>

#include "encode/image.h"

namespace cablefilm {

class JpegEncoder {
 public:
  explicit JpegEncoder(int quality = 85);  // 1..100; throws Error
  ~JpegEncoder();
  JpegEncoder(const JpegEncoder&) = delete;
  JpegEncoder& operator=(const JpegEncoder&) = delete;

  // The JPEG file's bytes (4:2:0, baseline) of an RGBA image; the alpha is ignored.
  std::string Encode(const Image& image);

 private:
  void* handle_ = nullptr;  // tjhandle
  int quality_;
};

}  // namespace cablefilm
