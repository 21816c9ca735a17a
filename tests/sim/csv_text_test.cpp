// CSV fields with the user's text in them (vehicle names, messages) are quoted as RFC 4180 says
// and split back to the same text.
#include "core/csv_text.h"

#include <gtest/gtest.h>

using namespace cosim;

TEST(CsvText, FieldsWithCommasQuotesOrLineBreaksAreQuotedAndSplitBackUnchanged) {
  EXPECT_EQ(csvField("uav1"), "uav1");
  EXPECT_EQ(csvField("a,b"), "\"a,b\"");
  EXPECT_EQ(csvField("q\"x'y"), "\"q\"\"x'y\"");
  const std::vector<std::string> names = {"plain", "a,b", "q\"x'y", "", "\",\"", "x\r"};
  std::string line;
  for (const auto& n : names) {
    if (!line.empty()) line += ',';
    line += csvField(n);
  }
  std::vector<std::string> fields;
  ASSERT_TRUE(splitCsvRecord("1.5," + line, fields));
  ASSERT_EQ(fields.size(), names.size() + 1);
  EXPECT_EQ(fields[0], "1.5");
  for (std::size_t i = 0; i < names.size(); ++i) EXPECT_EQ(fields[i + 1], names[i]);
}

TEST(CsvText, UnbalancedQuotesAreNotARecord) {
  std::vector<std::string> fields;
  EXPECT_FALSE(splitCsvRecord("1,\"a,b", fields));     // never closed
  EXPECT_FALSE(splitCsvRecord("1,\"a\"b,2", fields));  // text after the closing quote
  EXPECT_FALSE(splitCsvRecord("1,a\"b", fields));      // a quote inside an unquoted field
  EXPECT_TRUE(splitCsvRecord("1,,", fields));
  EXPECT_EQ(fields.size(), 3u);
}
