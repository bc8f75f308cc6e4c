#include "live/content_disposition.h"

#include <cstddef>

namespace cablefilm {
namespace {

// The length of the UTF-8 sequence at text[i] (1 to 4), or 0 if none starts there: a stray
// continuation byte, a truncated, overlong or surrogate sequence, beyond U+10FFFF.
std::size_t Utf8Length(const std::string& text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char b = byte(i);
  if (b < 0x80) return 1;
  const std::size_t n = b >= 0xC2 && b <= 0xDF ? 2 : b >= 0xE0 && b <= 0xEF ? 3
                        : b >= 0xF0 && b <= 0xF4 ? 4 : 0;
  if (n == 0 || i + n > text.size()) return 0;
  for (std::size_t k = 1; k < n; ++k)
    if ((byte(i + k) & 0xC0) != 0x80) return 0;
  const unsigned char c = byte(i + 1);
  if ((b == 0xE0 && c < 0xA0) || (b == 0xED && c > 0x9F) || (b == 0xF0 && c < 0x90) ||
      (b == 0xF4 && c > 0x8F))
    return 0;
  return n;
}

// RFC 5987's attr-char: sent as it is in filename*; every other byte is %HH.
bool IsAttrChar(unsigned char c) {
  if ((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9')) return true;
  for (const char* p = "!#$&+-.^_`|~"; *p; ++p)
    if (c == static_cast<unsigned char>(*p)) return true;
  return false;
}

}  // namespace

std::string ContentDisposition(const std::string& filename) {
  static const char kHex[] = "0123456789ABCDEF";
  std::string ascii, encoded;
  for (std::size_t i = 0; i < filename.size();) {
    const std::size_t n = Utf8Length(filename, i);
    if (n == 0) {  // not UTF-8: no character to name
      ascii += '_';
      encoded += '_';
      ++i;
      continue;
    }
    const unsigned char c = static_cast<unsigned char>(filename[i]);
    const bool plain = n == 1 && c >= 0x20 && c < 0x7F && c != '"' && c != '\\' && c != '%';
    ascii += plain ? static_cast<char>(c) : '_';
    for (std::size_t k = i; k < i + n; ++k) {
      const unsigned char b = static_cast<unsigned char>(filename[k]);
      if (IsAttrChar(b)) {
        encoded += static_cast<char>(b);
      } else {
        encoded += '%';
        encoded += kHex[b >> 4];
        encoded += kHex[b & 15];
      }
    }
    i += n;
  }
  return "Content-Disposition: attachment; filename=\"" + ascii + "\"; filename*=UTF-8''" +
         encoded + "\r\n";
}

}  // namespace cablefilm
