// Issue 11, defect 8: untrusted text (scene keys and names, table lines, titles, paths) is
// printed escaped: no terminal escape sequence, control character or stray byte gets through.
#include <gtest/gtest.h>

#include <string>

#include "scene/text_escape.h"

namespace cablefilm {
namespace {

TEST(TextEscape, PlainTextAndUtf8PassUnchanged) {
  EXPECT_EQ(EscapeText("Sample mooring line, Polachek et al. 1963"),
            "Sample mooring line, Polachek et al. 1963");
  EXPECT_EQ(EscapeText("caténaire \xE2\x80\x94 \xE6\xB5\xB7 \xF0\x9F\x8C\x8A"),
            "caténaire \xE2\x80\x94 \xE6\xB5\xB7 \xF0\x9F\x8C\x8A");
  EXPECT_EQ(EscapeText(""), "");
}

TEST(TextEscape, ControlCharactersAndEscapeSequences) {
  EXPECT_EQ(EscapeText("\x1b[31mred\x1b[0m"), "\\x1B[31mred\\x1B[0m");
  EXPECT_EQ(EscapeText("\x1b]0;title\x07"), "\\x1B]0;title\\x07");
  EXPECT_EQ(EscapeText(std::string("a\0b", 3)), "a\\x00b");
  EXPECT_EQ(EscapeText("tab\there\r\nline"), "tab\\there\\r\\nline");
  EXPECT_EQ(EscapeText("back\\slash\x7f"), "back\\\\slash\\x7F");
}

TEST(TextEscape, BytesThatAreNotUtf8AndHiddenCodePoints) {
  EXPECT_EQ(EscapeText("\xff\xfe"), "\\xFF\\xFE");
  EXPECT_EQ(EscapeText("\x9b" "2J"), "\\x9B2J");            // a raw 8-bit CSI
  EXPECT_EQ(EscapeText("\xC2\x9B" "2J"), "\\u{009B}2J");     // CSI as UTF-8 (C1 control)
  EXPECT_EQ(EscapeText("\xC0\xAF"), "\\xC0\\xAF");           // overlong
  EXPECT_EQ(EscapeText("\xED\xA0\x80"), "\\xED\\xA0\\x80");  // a surrogate
  EXPECT_EQ(EscapeText("\xE2\x80"), "\\xE2\\x80");           // cut short
  EXPECT_EQ(EscapeText("abc\xE2\x80\xAE" "cba"), "abc\\u{202E}cba");  // right-to-left override
}

TEST(TextEscape, QuotedText) {
  EXPECT_EQ(QuoteText("wire"), "\"wire\"");
  EXPECT_EQ(QuoteText("say \"hi\"\n"), "\"say \\\"hi\\\"\\n\"");
}

}  // namespace
}  // namespace cablefilm
