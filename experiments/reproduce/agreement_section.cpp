#include "experiments/reproduce/agreement_section.h"

#include <algorithm>

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

std::vector<std::string> agreementLines(const std::string& markdown) {
  const std::string heading = "## Where we agree and where we differ\n";
  std::vector<std::string> lines;
  const std::size_t at = markdown.find(heading);
  if (at == std::string::npos) return lines;
  std::size_t pos = at + heading.size();
  while (pos < markdown.size() && markdown[pos] == '\n') ++pos;
  while (pos < markdown.size() && markdown.compare(pos, 2, "- ") == 0) {
    const std::size_t end = std::min(markdown.find('\n', pos), markdown.size());
    lines.push_back(markdown.substr(pos + 2, end - pos - 2));
    pos = end + 1;
  }
  return lines;
}

}  // namespace cosim::reproduce
