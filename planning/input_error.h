#pragma once
// The one error type for bad input anywhere in the program. The command line turns it into
// one line on stderr ("file: place: problem") and exit status 2.
#include <stdexcept>
#include <string>

namespace cosim {

class InputError : public std::runtime_error {
 public:
  // file: the file (or "command line"); place: a line/key such as "line 4, key planner.name";
  // problem: what is wrong, in words a user can act on.
  InputError(std::string file, std::string place, std::string problem)
      : std::runtime_error(compose(file, place, problem)),
        file_(std::move(file)),
        place_(std::move(place)),
        problem_(std::move(problem)) {}

  const std::string& file() const { return file_; }
  const std::string& place() const { return place_; }
  const std::string& problem() const { return problem_; }

 private:
  static std::string compose(const std::string& file, const std::string& place,
                             const std::string& problem) {
    std::string s = file.empty() ? std::string("input") : file;
    if (!place.empty()) s += ": " + place;
    return s + ": " + problem;
  }
  std::string file_, place_, problem_;
};

}  // namespace cosim
