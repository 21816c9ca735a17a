// "Did you mean": the nearest known name by edit distance, only for slips of a few keystrokes.
#include "core/name_suggestion.h"

#include <gtest/gtest.h>

namespace cosim {
namespace {

TEST(NameSuggestion, EditDistanceCountsInsertionsDeletionsSubstitutionsAndSwaps) {
  EXPECT_EQ(editDistance("astar", "astar"), 0u);
  EXPECT_EQ(editDistance("thetastar", "theta_star"), 1u);   // insertion
  EXPECT_EQ(editDistance("rrt_starr", "rrt_star"), 1u);     // deletion
  EXPECT_EQ(editDistance("asrar", "astar"), 1u);            // substitution
  EXPECT_EQ(editDistance("resolutoin", "resolution"), 1u);  // adjacent swap: one slip
  EXPECT_EQ(editDistance("", "abc"), 3u);
  EXPECT_EQ(editDistance("kitten", "sitting"), 3u);  // Levenshtein's classic example
}

TEST(NameSuggestion, SuggestsOnlyNearMisses) {
  const std::vector<std::string> planners = {"astar", "theta_star", "lazy_theta_star",
                                             "rrt",   "rrt_star",   "prm"};
  EXPECT_EQ(closestName("thetastar", planners), "theta_star");
  EXPECT_EQ(closestName("rrt_str", planners), "rrt_star");
  EXPECT_EQ(closestName("teleport", planners), "");  // not a slip of any of them
  EXPECT_EQ(closestName("rrt", planners), "");       // a known name needs no suggestion
  EXPECT_EQ(closestName("x", {"a", "prm"}), "");     // one letter would "match" any letter
  EXPECT_EQ(didYouMean("wrld", {"world", "vehicles"}), "did you mean 'world'?");
  EXPECT_EQ(didYouMean("zzz_probe", {"world", "vehicles"}), "");
}

}  // namespace
}  // namespace cosim
