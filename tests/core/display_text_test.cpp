// The user's bytes placed into messages and files: control bytes and broken UTF-8 shown as \xNN,
// long values cut short, and number text that strtod would read but no table should hold.
#include "core/display_text.h"

#include <gtest/gtest.h>

#include <string>

#include "core/decimal_text.h"
#include "core/input_error.h"

// GCC 12 warns -Wrestrict, -Warray-bounds, -Wstringop-overflow inside libstdc++ where a string is
// assigned or concatenated once inlined (GCC bug 105329, a false positive).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wrestrict"
#pragma GCC diagnostic ignored "-Warray-bounds"
#pragma GCC diagnostic ignored "-Wstringop-overflow"
#endif

using namespace cosim;

TEST(DisplayText, KeepsValidUtf8AndEscapesControlAndBrokenBytes) {
  EXPECT_EQ(displayText("q\"x'y]]> <!--<script> a&b\\"), "q\"x'y]]> <!--<script> a&b\\");
  EXPECT_EQ(displayText("Fl\xc3\xbcge \xe2\x82\xac \xf0\x9f\x9a\x81"),
            "Fl\xc3\xbcge \xe2\x82\xac \xf0\x9f\x9a\x81");  // two, three and four bytes
  EXPECT_EQ(displayText(std::string("a\x1b[31m\nb\0c", 10)), "a\\x1b[31m\\x0ab\\x00c");
  EXPECT_EQ(displayText("\xff\xfe"), "\\xff\\xfe");
  EXPECT_EQ(displayText("\xc3"), "\\xc3");                    // cut short
  EXPECT_EQ(displayText("\xc0\xaf"), "\\xc0\\xaf");           // overlong '/'
  EXPECT_EQ(displayText("\xed\xa0\x80"), "\\xed\\xa0\\x80");  // a surrogate
  EXPECT_EQ(displayText("\x7f"), "\\x7f");
}

TEST(QuotedExcerpt, QuotesAShortPrefixWithNonAsciiEscaped) {
  EXPECT_EQ(quotedExcerpt("fast"), "'fast'");
  EXPECT_EQ(quotedExcerpt(std::string(50, 'x'), 40), "'" + std::string(40, 'x') + "...'");
  EXPECT_EQ(quotedExcerpt("\x89PNG\r\n\x1a", 40), "'\\x89PNG\\x0d\\x0a\\x1a'");
  EXPECT_EQ(quotedExcerpt("\xc3\xbc"), "'\\xc3\\xbc'");
}

TEST(SetAssignmentPlace, CutsAnAssignmentAfterEightyCharacters) {
  EXPECT_EQ(setAssignmentPlace("planner.name=astar"), "--set planner.name=astar");
  const std::string huge = "planner.resolution=" + std::string(1080000, '1');
  EXPECT_EQ(setAssignmentPlace(huge), "--set " + huge.substr(0, 80) + "...");
}

TEST(DecimalText, AcceptsDecimalNumbersOnly) {
  for (const char* good : {"1", "-0.5", "+2", ".5", "5.", "1e-3", "1E+9", "0.000", "1e999"})
    EXPECT_TRUE(isDecimalNumberText(good)) << good;
  for (const char* bad : {"", "0x10", "0X1p3", "inf", "-inf", "nan", "NaN", "infinity", ".", "-",
                          "e5", "1e", "1e+", "1.2.3", " 1", "1 ", "1,5", "--1", "1f"})
    EXPECT_FALSE(isDecimalNumberText(bad)) << bad;
}
