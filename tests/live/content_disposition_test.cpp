// The Content-Disposition header of the live view's downloads, built from the scene file's
// name: whatever the name holds, one header line, its quoted fallback whole, its UTF-8 name
// percent-encoded (RFC 6266, RFC 5987).
#include <gtest/gtest.h>

#include <string>

#include "live/content_disposition.h"

namespace cablefilm {
namespace {

// The header must be one line: no CR, LF or other control character before its own CRLF.
void ExpectOneLine(const std::string& header) {
  ASSERT_GE(header.size(), 2u);
  EXPECT_EQ(header.substr(header.size() - 2), "\r\n");
  for (std::size_t i = 0; i + 2 < header.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(header[i]);
    EXPECT_TRUE(c >= 0x20 && c < 0x7F) << "byte " << i << " is " << int(c) << " in " << header;
  }
}

TEST(ContentDisposition, PlainNameAsIs) {
  const std::string h = ContentDisposition("polachek1963-live-timeseries.csv");
  EXPECT_EQ(h, "Content-Disposition: attachment; filename=\"polachek1963-live-timeseries.csv\"; "
               "filename*=UTF-8''polachek1963-live-timeseries.csv\r\n");
  ExpectOneLine(h);
}

TEST(ContentDisposition, LineBreaksCannotStartAnotherHeader) {
  const std::string h = ContentDisposition("x\r\nSet-Cookie: cf=evil\r\nX-A: 1-t3.png");
  EXPECT_EQ(h,
            "Content-Disposition: attachment; filename=\"x__Set-Cookie: cf=evil__X-A: 1-t3.png\"; "
            "filename*=UTF-8''x%0D%0ASet-Cookie%3A%20cf%3Devil%0D%0AX-A%3A%201-t3.png\r\n");
  ExpectOneLine(h);
}

TEST(ContentDisposition, QuotesBackslashesAndPercentsCannotBreakTheQuotedName) {
  const std::string h = ContentDisposition("a\"b\\c%41d;e.csv");
  EXPECT_EQ(h, "Content-Disposition: attachment; filename=\"a_b_c_41d;e.csv\"; "
               "filename*=UTF-8''a%22b%5Cc%2541d%3Be.csv\r\n");
  ExpectOneLine(h);
}

TEST(ContentDisposition, OtherControlCharactersAreReplaced) {
  const std::string h = ContentDisposition(std::string("t\tab\0nul\x1b[31m\x7f", 14) + ".png");
  EXPECT_EQ(h, "Content-Disposition: attachment; filename=\"t_ab_nul_[31m_.png\"; "
               "filename*=UTF-8''t%09ab%00nul%1B%5B31m%7F.png\r\n");
  ExpectOneLine(h);
}

TEST(ContentDisposition, Utf8NamesKeepTheirCharactersInFilenameStar) {
  // "Åsgard ø 系泊" : one "_" a character in the fallback, its UTF-8 bytes percent-encoded.
  const std::string h = ContentDisposition("\xC3\x85sgard \xC3\xB8 \xE7\xB3\xBB\xE6\xB3\x8A.csv");
  EXPECT_EQ(h, "Content-Disposition: attachment; filename=\"_sgard _ __.csv\"; "
               "filename*=UTF-8''%C3%85sgard%20%C3%B8%20%E7%B3%BB%E6%B3%8A.csv\r\n");
  ExpectOneLine(h);
  // A four-byte character (U+1F30A) is one character too.
  EXPECT_EQ(ContentDisposition("\xF0\x9F\x8C\x8A"),
            "Content-Disposition: attachment; filename=\"_\"; filename*=UTF-8''%F0%9F%8C%8A\r\n");
}

TEST(ContentDisposition, BytesThatAreNotUtf8AreReplacedInBoth) {
  // A lone continuation byte, a truncated sequence, an overlong "/" and a surrogate: what the
  // name's UTF-8 cannot say is "_" in filename* too, so it stays valid UTF-8.
  const std::string h = ContentDisposition("a\x80" "b\xC3" "c\xC0\xAF" "d\xED\xA0\x80" "e");
  EXPECT_EQ(h, "Content-Disposition: attachment; filename=\"a_b_c__d___e\"; "
               "filename*=UTF-8''a_b_c__d___e\r\n");
  ExpectOneLine(h);
}

TEST(ContentDisposition, EveryByteGivesOneLine) {
  for (int b = 0; b < 256; ++b) {
    const std::string name = "n" + std::string(1, static_cast<char>(b)) + ".csv";
    ExpectOneLine(ContentDisposition(name));
  }
}

}  // namespace
}  // namespace cablefilm
