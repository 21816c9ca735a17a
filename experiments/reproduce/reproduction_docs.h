#pragma once
// docs/reproductions.md quotes the committed full runs' reports (experiments/reproduce/results/
// NAME.json) instead of copying their figures by hand, so the page cannot drift from them: for
// every such report, its verdict list holds a generated block (the report's closing "Where we
// agree and where we differ" lines, from the JSON's "agreement") and its run-time table the
// JSON's "run_time_s". A test compares the page with what these functions make of the committed
// reports; COSIM_UPDATE_REPRODUCTION_DOCS=1 rewrites it.
#include <map>
#include <string>

namespace cosim::reproduce {

// Where the committed full-run reports live, relative to the project.
inline constexpr const char* kCommittedReportsDir = "experiments/reproduce/results";

// The verdict block of one report, given its NAME.json text; `json_path` is named in the block's
// markers and in errors. Throws InputError (the path, what is missing) for a report that is not a
// timed full run or lacks "agreement".
std::string reproductionVerdictBlock(const std::string& json_path, const std::string& json_text);

// `doc` (docs/reproductions.md's text) with every report's block and run time put in: an existing
// block is replaced, else the hand-written item "- **NAME**..." (with its indented lines) of the
// verdict list (from the line "Verdicts of the full runs" on) is, else the block is added at the
// end of that list; the run-time table's "full run" cell of the
// row "| `NAME` |" becomes the JSON's run_time_s. `reports` maps each report's path (as named in
// the markers) to its JSON text. Throws InputError if the page has no such table row.
std::string reproductionDocsWithReports(std::string doc,
                                        const std::map<std::string, std::string>& reports);

}  // namespace cosim::reproduce
