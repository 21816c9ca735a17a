#pragma once
// What the LaCAM* paper publishes about the MovingAI MAPF benchmark, to set beside our runs:
// K. Okumura, "Improving LaCAM for Scalable Eventually Optimal Multi-Agent Pathfinding", IJCAI
// 2023, Fig. 1 (also on the project page, kei18.github.io/lacam2, as "performance.png").
#include <string>

namespace cosim {

// True for the 33 maps of the MAPF benchmark (Stern et al., SoCS 2019) that the paper's 13,900
// instances come from (map name without folder or ".map").
bool inLacamStarBenchmark(const std::string& map_name);

// Markdown: the published figures, and what they are (and are not) for `map_name`.
std::string lacamStarPublishedMarkdown(const std::string& map_name);

}  // namespace cosim
