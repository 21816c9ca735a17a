#pragma once
// "Did you mean ...?" for names the user typed (planner names, parameter keys, scenario keys):
// the closest known name by edit distance, if it is close enough to be a slip of the fingers.
#include <string>
#include <vector>

namespace cosim {

// Levenshtein distance (insertions, deletions, substitutions; Levenshtein 1966), with an adjacent
// transposition counting as one edit (Damerau 1964: "resolutoin" is one slip from "resolution").
std::size_t editDistance(const std::string& a, const std::string& b);

// The candidate nearest to `name`, if it is at most 2 edits away and fewer edits than a third of
// its length plus one (so "a" does not suggest "x"); "" otherwise or if `name` is a candidate.
std::string closestName(const std::string& name, const std::vector<std::string>& candidates);

// "did you mean 'resolution'?" for closestName, or "".
std::string didYouMean(const std::string& name, const std::vector<std::string>& candidates);

}  // namespace cosim
