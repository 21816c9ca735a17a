#pragma once
// The closing section every thesis reproduction ends with, "Where we agree and where we differ":
// one line per thesis finding, saying whether our run agrees, differs for a stated reason, or
// differs for a reason we could not find (and what was tried). Where a finding can be checked in
// code, the verdict is computed from this run's numbers, so the line stays true when they change.
#include <string>
#include <vector>

namespace cosim::reproduce {

struct Finding {
  enum class Verdict { kAgrees, kDiffers, kDiffersUnknown };
  std::string claim;  // the thesis's finding, with its table or section
  std::string ours;   // what our run shows, with the numbers
  Verdict verdict = Verdict::kAgrees;
  std::string reason;  // why it differs; for kDiffersUnknown, what was tried
};

// A finding checked in code: agrees when `agrees` holds, else differs because `why_differs`
// (or, with reason_known false, differs for a reason unknown after trying `why_differs`).
Finding checkedFinding(const std::string& claim, bool agrees, const std::string& ours,
                       const std::string& why_differs, bool reason_known = true);

// A finding judged in text (no number of ours can decide it by itself).
Finding statedFinding(const std::string& claim, Finding::Verdict verdict, const std::string& ours,
                      const std::string& reason = "");

// "## Where we agree and where we differ" and one line per finding:
// "- claim: **agrees** (ours)." / "**differs** (ours), because reason." /
// "**differs, reason unknown** (ours; tried: reason)."
std::string agreementSection(const std::vector<Finding>& findings);

// The finding lines ("- ...") of the agreement section in a report's markdown, without their
// "- "; empty if the report has no such section. NAME.json carries them as "agreement", and
// docs/reproductions.md quotes them from there.
std::vector<std::string> agreementLines(const std::string& markdown);

}  // namespace cosim::reproduce
