#pragma once
// Files and folders for tests: a file's whole content, and a folder of the test's own in the
// system's temporary folder (the process id in its name keeps tests that run at once apart).
#include <filesystem>
#include <string>

namespace cosim::test {

// The file's bytes as they are; "" if it cannot be read (a file not written yet reads as empty).
std::string slurp(const std::filesystem::path& file);

// TMP/cosim-NAME-PID with nothing at it: whatever an earlier run left there is removed, and the
// folder is not created (the test or the program under test creates it).
std::filesystem::path freshDir(const std::string& name);

// freshDir(name), created and empty.
std::filesystem::path makeFreshDir(const std::string& name);

}  // namespace cosim::test
