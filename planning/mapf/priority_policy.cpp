#include "planning/mapf/priority_policy.h"

#include <algorithm>
#include <numeric>

#include "core/input_error.h"

namespace cosim {

PriorityPolicy parsePriorityPolicy(const std::string& name) {
  if (name == "fixed") return PriorityPolicy::kFixed;
  if (name == "dynamic") return PriorityPolicy::kDynamic;
  throw InputError("", "priorities", "must be 'fixed' or 'dynamic', not '" + name + "'");
}

const char* priorityPolicyName(PriorityPolicy policy) {
  return policy == PriorityPolicy::kFixed ? "fixed" : "dynamic";
}

std::vector<int> planningOrder(const std::vector<int>& priority) {
  std::vector<int> order(priority.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return priority[a] > priority[b]; });
  return order;
}

}  // namespace cosim
