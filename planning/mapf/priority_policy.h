#pragma once
// How the prioritised planners (CA*, HCA*, WHCA*) order their agents (seed 004 §2.5, §4.5).
#include <string>
#include <vector>

namespace cosim {

enum class PriorityPolicy {
  kFixed,    // the order of the instance (scenario file), never changed
  kDynamic,  // an agent that finds no route gets the highest priority and the plan is redone
};

PriorityPolicy parsePriorityPolicy(const std::string& name);  // "fixed" or "dynamic"
const char* priorityPolicyName(PriorityPolicy policy);

// The planning order: higher priority first, then lower agent index.
std::vector<int> planningOrder(const std::vector<int>& priority);

}  // namespace cosim
