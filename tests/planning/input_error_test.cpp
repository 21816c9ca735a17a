// InputError's one-line message: control bytes quoted from the input are escaped in what()
// (a NUL used to cut the message short), the parts keep them raw; an error raised where the
// file is unknown can be given the file afterwards.
#include "core/input_error.h"

#include <gtest/gtest.h>

namespace cosim {
namespace {

TEST(InputError, WhatEscapesControlBytesAndKeepsTheRestOfTheMessage) {
  const std::string nul(1, '\0');
  const InputError e("map\x1b.map", "line 5", "unknown map character '" + nul + "' here");
  EXPECT_EQ(std::string(e.what()), "map\\x1b.map: line 5: unknown map character '\\x00' here");
  EXPECT_EQ(e.problem(), "unknown map character '" + nul + "' here");  // raw, for callers
}

TEST(InputError, PrintableTextEscapesOnlyControlBytes) {
  EXPECT_EQ(printableText(std::string("a\tb\nc\x7f") + "\xc3\xa9"), "a\\x09b\\x0ac\\x7f\xc3\xa9");
  EXPECT_EQ(printableText("\\x00"), "\\x00");  // already escaped text stays as it is
}

TEST(InputError, InFileFillsOnlyAMissingFile) {
  const InputError unknown("", "grid", "too large");
  EXPECT_EQ(std::string(unknown.what()), "input: grid: too large");
  EXPECT_EQ(std::string(unknown.inFile("a.yaml").what()), "a.yaml: grid: too large");
  const InputError known("b.map", "line 2", "bad");
  EXPECT_EQ(known.inFile("a.yaml").file(), "b.map");
}

}  // namespace
}  // namespace cosim
