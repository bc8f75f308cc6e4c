#pragma once
// A CSV line formatted into a buffer of its own with std::to_chars, then written at once:
// the text of printf's "%.<precision>g" and "%d" byte for byte (the C++ standard defines
// to_chars with a precision as printf's conversion in the "C" locale: the same digits,
// exponent, "inf" and "nan"), at a fraction of printf's cost (glibc's %g works in
// multi-precision arithmetic).
// No allocation: the buffer lives on the stack. The text reaches the stream when the CsvLine
// goes (or its buffer fills): let it go before the file is committed.
#include <charconv>
#include <cstdio>
#include <cstring>
#include <string_view>

namespace cablefilm {

class CsvLine {
 public:
  // "%.<precision>g" of `v` (precision 1 to 17).
  CsvLine& G(double v, int precision) {
    Room(32);
    end_ = std::to_chars(end_, limit_, v, std::chars_format::general, precision).ptr;
    return *this;
  }
  CsvLine& Int(long v) {
    Room(24);
    end_ = std::to_chars(end_, limit_, v).ptr;
    return *this;
  }
  CsvLine& Text(std::string_view s) {
    if (s.size() > static_cast<std::size_t>(limit_ - end_)) {
      Flush();
      if (s.size() > sizeof buffer_) {
        std::fwrite(s.data(), 1, s.size(), file_);
        return *this;
      }
    }
    std::memcpy(end_, s.data(), s.size());
    end_ += s.size();
    return *this;
  }
  CsvLine& Char(char c) {
    Room(1);
    *end_++ = c;
    return *this;
  }
  CsvLine& Comma() { return Char(','); }

  explicit CsvLine(std::FILE* file) : file_(file) {}
  ~CsvLine() { Flush(); }  // the stream's own errors are the file's (AtomicFile::Commit checks)
  CsvLine(const CsvLine&) = delete;
  CsvLine& operator=(const CsvLine&) = delete;

 private:
  void Room(std::ptrdiff_t n) {
    if (limit_ - end_ < n) Flush();
  }
  void Flush() {
    if (end_ != buffer_) std::fwrite(buffer_, 1, static_cast<std::size_t>(end_ - buffer_), file_);
    end_ = buffer_;
  }

  std::FILE* file_;
  char buffer_[512];
  char* end_ = buffer_;
  char* const limit_ = buffer_ + sizeof buffer_;
};

}  // namespace cablefilm
