#pragma once
// The temporary name a file is written under before it is renamed into place (outputs appear
// complete or not at all). ".<name><tag><pid>" beside the target, hidden, unique per process;
// the target's name is shortened when needed so that the temporary name fits the file
// system's 255-byte limit for a name (a valid 254-byte output name must not fail on it).
#include <filesystem>
#include <string>

namespace cosim {

std::filesystem::path temporaryNameFor(const std::filesystem::path& target, const std::string& tag);

}  // namespace cosim
