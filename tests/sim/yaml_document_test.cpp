// Every YAML document cosim reads is checked for what yaml-cpp lets through and the readers
// after it cannot survive: alias cycles, alias bombs, deep nesting, keys given twice.
#include "sim/yaml_document.h"

#include <gtest/gtest.h>

#include <string>

#include "core/input_error.h"

using namespace cosim;

namespace {

// "place | problem" of the InputError loading `text` throws, or "" (and a test failure).
std::string refusal(const std::string& text) {
  try {
    loadYamlDocument(text, "doc.yaml");
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "doc.yaml");
    return e.place() + " | " + e.problem();
  }
  ADD_FAILURE() << "accepted:\n" << text;
  return "";
}

TEST(YamlDocument, AnAliasInsideItsOwnAnchorIsACycleNamedAtItsKey) {
  const std::string why = refusal("name: x\nset: &s {a: *s}\n");
  EXPECT_NE(why.find("line 2, key set.a | an alias refers to a node that contains it"),
            std::string::npos)
      << why;
}

TEST(YamlDocument, ACycleThroughASequenceIsFoundToo) {
  EXPECT_NE(refusal("a: &x [1, [2, *x]]\n").find("key a[1][1] |"), std::string::npos);
}

TEST(YamlDocument, SharedAliasesThatAreNotCyclesAreAccepted) {
  const YAML::Node n = loadYamlDocument(
      "base: &b {x: 1, y: [1, 2]}\nfirst: *b\nsecond: *b\nlist: [*b, *b]\n", "doc.yaml");
  EXPECT_EQ(n["second"]["y"][1].as<int>(), 2);
  EXPECT_EQ(n["list"].size(), 2u);
}

TEST(YamlDocument, AliasesAreCountedOncePerUseSoABombIsRefused) {
  // Nine levels of ten aliases each: 10^9 values in a few hundred bytes.
  std::string text = "l0: &l0 [x, x, x, x, x, x, x, x, x, x]\n";
  for (int i = 1; i <= 9; ++i) {
    const std::string prev = "*l" + std::to_string(i - 1);
    std::string list;
    for (int k = 0; k < 10; ++k) list += (k ? ", " : "") + prev;
    text += "l" + std::to_string(i) + ": &l" + std::to_string(i) + " [" + list + "]\n";
  }
  EXPECT_LT(text.size(), 1000u);
  EXPECT_NE(refusal(text).find("more than 1000000 values once its aliases are expanded"),
            std::string::npos);
}

TEST(YamlDocument, NestingDeeperThanTheLimitIsRefusedAtItsKey) {
  std::string deep = "a: ";
  for (int i = 0; i < kMaxYamlDepth; ++i) deep += "[";
  for (int i = 0; i < kMaxYamlDepth; ++i) deep += "]";
  EXPECT_NE(refusal(deep + "\n").find("nested more than 64 levels deep"), std::string::npos);
  // One level less is fine: the root mapping is the first level.
  std::string ok = "a: ";
  for (int i = 0; i < kMaxYamlDepth - 1; ++i) ok += "[";
  for (int i = 0; i < kMaxYamlDepth - 1; ++i) ok += "]";
  EXPECT_NO_THROW(loadYamlDocument(ok + "\n", "doc.yaml"));
}

TEST(YamlDocument, AKeyGivenTwiceIsRefusedAtAnyLevel) {
  EXPECT_NE(refusal("planner: {name: astar}\nsim: {}\nplanner: {name: rrt}\n")
                .find("line 3, key planner | key 'planner' is given twice"),
            std::string::npos);
  EXPECT_NE(refusal("world:\n  bounds: {min: [0, 0, 0], min: [1, 1, 1]}\n")
                .find("key world.bounds.min | key 'min' is given twice"),
            std::string::npos);
  EXPECT_NE(refusal("v:\n  - {name: a}\n  - {name: b, name: c}\n").find("key v[1].name"),
            std::string::npos);
}

TEST(YamlDocument, AKeyThatIsAListOrMappingIsRefused) {
  EXPECT_NE(refusal("? [a, b]\n: 1\n").find("a key must be a plain name"), std::string::npos);
}

// yaml-cpp's Load reads the first document: the keys after '---' were silently ignored.
TEST(YamlDocument, ASecondDocumentIsRefusedAtItsLine) {
  const std::string why = refusal("world: {}\n# the rest\n---\nvehicles: []\n");
  EXPECT_EQ(why.substr(0, why.find(" | ")), "line 3") << why;
  EXPECT_NE(why.find("a second YAML document"), std::string::npos) << why;
  // A document that starts with '---' or ends with '...' is one document.
  EXPECT_NO_THROW(loadYamlDocument("---\na: 1\n...\n", "doc.yaml"));
}

TEST(YamlDocument, MalformedTextNamesItsLine) {
  EXPECT_NE(refusal("a: 1\nb: [2\n").find("malformed YAML"), std::string::npos);
}

}  // namespace
