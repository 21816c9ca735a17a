// The flattener behind the HTML report's metric tables and a sweep's results.csv columns.
#include "core/json_flatten.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <stdexcept>

using namespace cosim;

namespace {
using Pair = std::pair<std::string, std::string>;
}

TEST(JsonFlatten, KeyPathsFollowDocumentOrderAndNesting) {
  const FlatJson f =
      flattenJson(R"({"z": 1.5, "b": {"c": "x\"y"}, "v": [{"d": true}, {"d": null}], "e": {}})");
  ASSERT_EQ(f.size(), 4u);
  EXPECT_EQ(f[0], Pair("z", "1.5"));
  EXPECT_EQ(f[1], Pair("b.c", "x\"y"));
  EXPECT_EQ(f[2], Pair("v[0].d", "true"));
  EXPECT_EQ(f[3], Pair("v[1].d", "null"));
}

TEST(JsonFlatten, NullTextIsTheCallersChoice) {
  const FlatJson f = flattenJson(R"({"rmse_m": null, "n": [[1, 2]]})", "");
  ASSERT_EQ(f.size(), 3u);
  EXPECT_EQ(f[0], Pair("rmse_m", ""));
  EXPECT_EQ(f[1], Pair("n[0][0]", "1"));
  EXPECT_EQ(f[2], Pair("n[0][1]", "2"));
}

TEST(JsonFlatten, NumbersAreWrittenAsJsonWritesThemAndStringsUnescaped) {
  const FlatJson f = flattenJson(R"({"a": 0.30000000000000004, "b": 1e-300, "c": -3,
                                    "d": 2.0, "s": "caf\u00e9\ttab"})");
  ASSERT_EQ(f.size(), 5u);
  EXPECT_EQ(f[0].second, "0.30000000000000004");
  EXPECT_EQ(f[1].second, "1e-300");
  EXPECT_EQ(f[2].second, "-3");
  EXPECT_EQ(f[3].second, "2.0");
  EXPECT_EQ(f[4].second, "caf\xc3\xa9\ttab");
}

TEST(JsonFlatten, DocumentAndTextGiveTheSamePairs) {
  const std::string text = R"({"k": {"m": [1, "two"]}})";
  EXPECT_EQ(flattenJsonDocument(nlohmann::ordered_json::parse(text)), flattenJson(text));
}

TEST(JsonFlatten, MalformedTextThrows) {
  EXPECT_THROW(flattenJson("{\"a\": "), std::runtime_error);
  EXPECT_THROW(flattenJson("{\"a\": 1} trailing"), std::runtime_error);
}
