// Reading back the JSON files cosim wrote: bad ones are InputErrors that point at the place.
#include "core/json_reading.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include "core/input_error.h"

using namespace cosim;

TEST(JsonReading, ParsesAndKeepsKeyOrder) {
  const nlohmann::ordered_json j = parseJsonText(R"({"b": 1, "a": [true]})", "x.json");
  EXPECT_EQ(j.begin().key(), "b");
  EXPECT_EQ(j["a"][0], true);
}

TEST(JsonReading, BadJsonNamesTheFileLineAndColumn) {
  try {
    parseJsonText("{\n  \"a\": 1,\n  \"b\": ]\n}\n", "run/run.json");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "run/run.json");
    EXPECT_EQ(e.place(), "line 3, column 8");  // the ']'
    EXPECT_NE(e.problem().find("not valid JSON: syntax error"), std::string::npos) << e.what();
  }
}

TEST(JsonReading, UnexpectedEndIsPlacedAfterTheLastCharacter) {
  try {
    parseJsonText("{\"a\": ", "m.json");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.place(), "line 1, column 7");
  }
}

TEST(JsonReading, AMissingFileIsAnInputErrorNamingIt) {
  const auto missing = std::filesystem::temp_directory_path() /
                       ("cosim-json-missing-" + std::to_string(::getpid())) / "metrics.json";
  try {
    readJsonFile(missing);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), missing.string());
  }
}

TEST(JsonReading, ReadsAFile) {
  const auto file = std::filesystem::temp_directory_path() /
                    ("cosim-json-read-" + std::to_string(::getpid()) + ".json");
  std::ofstream(file) << "{\"end_reason\": \"goal\"}\n";
  EXPECT_EQ(readJsonFile(file)["end_reason"], "goal");
  std::filesystem::remove(file);
}
