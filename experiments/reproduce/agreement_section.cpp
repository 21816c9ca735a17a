#include "experiments/reproduce/agreement_section.h"

namespace cosim::reproduce {

Finding checkedFinding(const std::string& claim, bool agrees, const std::string& ours,
                       const std::string& why_differs, bool reason_known) {
  Finding f;
  f.claim = claim;
  f.ours = ours;
  if (agrees) return f;
  f.verdict = reason_known ? Finding::Verdict::kDiffers : Finding::Verdict::kDiffersUnknown;
  f.reason = why_differs;
  return f;
}

Finding statedFinding(const std::string& claim, Finding::Verdict verdict, const std::string& ours,
                      const std::string& reason) {
  Finding f;
  f.claim = claim;
  f.ours = ours;
  f.verdict = verdict;
  f.reason = reason;
  return f;
}

std::string agreementSection(const std::vector<Finding>& findings) {
  std::string md = "## Where we agree and where we differ\n\n";
  for (const Finding& f : findings) {
    md += "- " + f.claim + ": ";
    switch (f.verdict) {
      case Finding::Verdict::kAgrees:
        md += "**agrees** (" + f.ours + ")";
        break;
      case Finding::Verdict::kDiffers:
        md += "**differs** (" + f.ours + "), because " + f.reason;
        break;
      case Finding::Verdict::kDiffersUnknown:
        md += "**differs, reason unknown** (" + f.ours + "; tried: " + f.reason + ")";
        break;
    }
    if (md.back() != '.') md += ".";
    md += "\n";
  }
  return md + "\n";
}

}  // namespace cosim::reproduce
