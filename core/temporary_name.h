#pragma once
// The temporary name a file is written under before it is renamed into place (outputs appear
// complete or not at all). ".<name><tag><pid>" beside the target, hidden, unique per process;
// the target's name is shortened when needed so that the temporary name fits the file
// system's 255-byte limit for a name (a valid 254-byte output name must not fail on it).
//
// The name is only a proposal: whatever already exists there (a file left by a crashed process
// with the same pid, or a symbolic link planted to make cosim write elsewhere) is neither
// followed, truncated nor removed. createTemporaryFile and createTemporaryFolder make a new entry
// exclusively (O_CREAT|O_EXCL|O_NOFOLLOW, mkdir) and take the next name, ".<name><tag><pid>-1",
// "-2", ..., when one is taken.
#include <filesystem>
#include <string>

namespace cosim {

std::filesystem::path temporaryNameFor(const std::filesystem::path& target, const std::string& tag);

struct TemporaryFile {
  std::filesystem::path path;
  int fd = -1;  // open for writing; the caller closes it
};

// A new, empty regular file (mode 0644 less the umask) under a temporary name beside `target`.
// Throws std::runtime_error naming `target` if none can be made.
TemporaryFile createTemporaryFile(const std::filesystem::path& target, const std::string& tag);

// A new, empty folder (mode 0755 less the umask) under a temporary name beside `target`; throws
// as above.
std::filesystem::path createTemporaryFolder(const std::filesystem::path& target,
                                            const std::string& tag);

}  // namespace cosim
