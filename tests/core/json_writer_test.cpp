// JsonObject, the writer of metrics.json and every other JSON file: numbers read back bit for bit,
// keys stay in the order they were added, and the text is valid JSON whatever the values.
#include "core/json_writer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <nlohmann/json.hpp>
#include <stdexcept>

using namespace cosim;

namespace {

// The number text after "key": in the writer's output, read back with strtod as any C reader
// would.
double readBack(const std::string& text, const std::string& key) {
  const std::string marker = "\"" + key + "\": ";
  const auto at = text.find(marker);
  EXPECT_NE(at, std::string::npos) << text;
  return std::strtod(text.c_str() + at + marker.size(), nullptr);
}

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

TEST(JsonObject, DoublesReadBackBitExactWithStrtod) {
  const double sum = 0.1 + 0.2;  // 0.30000000000000004: 10 significant digits would lose it
  const double tiny = 1e-300;
  const double third = 1.0 / 3.0;
  const std::string text = JsonObject().add("sum", sum).add("tiny", tiny).add("third", third).str();
  EXPECT_TRUE(sameBits(readBack(text, "sum"), sum)) << text;
  EXPECT_TRUE(sameBits(readBack(text, "tiny"), tiny)) << text;
  EXPECT_TRUE(sameBits(readBack(text, "third"), third)) << text;
  EXPECT_NE(text.find("\"sum\": 0.30000000000000004"), std::string::npos) << text;
  EXPECT_NE(text.find("\"tiny\": 1e-300"), std::string::npos) << text;
}

TEST(JsonObject, KeysKeepTheOrderTheyWereAddedIn) {
  JsonObject j;
  j.add("zeta", 1).add("alpha", 2).add("mid", 3);
  const std::string text = j.str();
  const auto z = text.find("\"zeta\""), a = text.find("\"alpha\""), m = text.find("\"mid\"");
  ASSERT_NE(m, std::string::npos);
  EXPECT_LT(z, a);
  EXPECT_LT(a, m);
  std::vector<std::string> keys;
  for (const auto& [k, v] : j.json().items()) keys.push_back(k);
  EXPECT_EQ(keys, (std::vector<std::string>{"zeta", "alpha", "mid"}));
}

TEST(JsonObject, AddingAKeyAgainReplacesItsValueInPlace) {
  const JsonObject j = JsonObject().add("a", 1).add("b", 2).add("a", 5);
  EXPECT_EQ(j.str(), "{\n  \"a\": 5,\n  \"b\": 2\n}");
}

TEST(JsonObject, NonFiniteNumbersBecomeNull) {
  const std::map<std::string, double> nested = {{"x", std::nan("")}, {"y", 1.5}};
  const JsonObject j = JsonObject()
                           .add("nan", std::nan(""))
                           .add("inf", std::numeric_limits<double>::infinity())
                           .add("ninf", -std::numeric_limits<double>::infinity())
                           .add("nested", nested);
  EXPECT_TRUE(j.json()["nan"].is_null());
  EXPECT_TRUE(j.json()["inf"].is_null());
  EXPECT_TRUE(j.json()["ninf"].is_null());
  EXPECT_TRUE(j.json()["nested"]["x"].is_null());
  EXPECT_EQ(j.json()["nested"]["y"].get<double>(), 1.5);
  const nlohmann::json back = nlohmann::json::parse(j.str());
  EXPECT_TRUE(back["nan"].is_null());
  EXPECT_EQ(JsonObject::number(std::nan("")), "null");
}

TEST(JsonObject, RawParsesItsTextIntoTheDocument) {
  JsonObject j;
  j.raw("list", "[1,{\"x\":2.5},null]");
  ASSERT_TRUE(j.json()["list"].is_array());
  EXPECT_EQ(j.json()["list"][1]["x"].get<double>(), 2.5);
  EXPECT_NE(j.str().find("\"x\": 2.5"), std::string::npos);  // parsed, not pasted: laid out
  EXPECT_THROW(j.raw("bad", "{\"a\": "), std::invalid_argument);
}

TEST(JsonObject, IntegersBooleansStringsAndNestedObjectsKeepTheirTypes) {
  const JsonObject inner = JsonObject().add("n", 7);
  const JsonObject j = JsonObject()
                           .add("size", std::numeric_limits<std::size_t>::max())
                           .add("long", -9000000000L)
                           .add("flag", true)
                           .add("c", "q\"uote\n")
                           .add("s", std::string("text"))
                           .add("inner", inner)
                           .add("names", std::map<std::string, std::string>{{"k", "v"}})
                           .addArray("items", {inner, inner});
  const nlohmann::ordered_json back = nlohmann::ordered_json::parse(j.str());
  EXPECT_EQ(back["size"].get<std::size_t>(), std::numeric_limits<std::size_t>::max());
  EXPECT_EQ(back["long"].get<long>(), -9000000000L);
  EXPECT_EQ(back["flag"], true);
  EXPECT_EQ(back["c"].get<std::string>(), "q\"uote\n");
  EXPECT_EQ(back["inner"]["n"].get<int>(), 7);
  EXPECT_EQ(back["names"]["k"].get<std::string>(), "v");
  EXPECT_EQ(back["items"].size(), 2u);
  EXPECT_EQ(back["items"][1]["n"].get<int>(), 7);
}

TEST(JsonObject, IndentShiftsEveryLineButTheFirst) {
  const JsonObject j = JsonObject().add("a", 1).add("b", JsonObject().add("c", 2));
  EXPECT_EQ(j.str(), "{\n  \"a\": 1,\n  \"b\": {\n    \"c\": 2\n  }\n}");
  EXPECT_EQ(j.str(1), "{\n    \"a\": 1,\n    \"b\": {\n      \"c\": 2\n    }\n  }");
}

TEST(JsonObject, BytesThatAreNotUtf8AreReplacedSoTheTextStaysJson) {
  const JsonObject j = JsonObject().add("name", std::string("uav\xff"));
  const nlohmann::json back = nlohmann::json::parse(j.str());
  EXPECT_EQ(back["name"].get<std::string>(), "uav\xef\xbf\xbd");  // U+FFFD
}

TEST(JsonObject, CopiesAreIndependent) {
  JsonObject a;
  a.add("x", 1);
  JsonObject b = a;
  b.add("y", 2);
  EXPECT_FALSE(a.json().contains("y"));
  JsonObject moved = std::move(b);
  EXPECT_TRUE(moved.json().contains("y"));
}

TEST(JsonObject, NumberIsTheShortestTextThatReadsBack) {
  EXPECT_EQ(JsonObject::number(0.1 + 0.2), "0.30000000000000004");
  EXPECT_EQ(JsonObject::number(2.0), "2.0");
  EXPECT_EQ(JsonObject::number(1e-5), "1e-05");
  EXPECT_EQ(JsonObject::quote("a\"b"), "\"a\\\"b\"");
}
