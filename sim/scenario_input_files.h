#pragma once
// Every file a run of a scenario reads besides the scenario text itself: the grid map, the world
// fragment (world.include) and the files it names, each vehicle's reference file, model file and
// a URDF's meshes. A sweep's job fingerprint hashes their contents, so that a resumed sweep
// reruns the jobs whose inputs changed (an edited fragment changed the collisions of a job whose
// scenario text stayed the same).
#include <filesystem>
#include <string>
#include <vector>

namespace cosim {

// From the scenario's text and --set overrides, without building anything. A file that does
// not exist is listed all the same (its absence is part of the job's inputs); what cannot be
// read is skipped (the run reports it). In a fixed order, without repeats.
std::vector<std::filesystem::path> scenarioInputFiles(const std::string& text,
                                                      const std::string& file,
                                                      const std::vector<std::string>& overrides);

}  // namespace cosim
