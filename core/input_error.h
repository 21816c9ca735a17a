#pragma once
// The one error type for bad input anywhere in the program. The command line turns it into
// one line on stderr ("file: place: problem") and exit status 2.
#include <stdexcept>
#include <string>

namespace cosim {

class InputError : public std::runtime_error {
 public:
  // file: the file (or "command line"); place: a line/key such as "line 4, key planner.name";
  // problem: what is wrong, in words a user can act on. Any of them may quote the user's bytes:
  // what() shows control characters escaped (see printableText), so the message stays one
  // readable line; file(), place() and problem() keep them as given.
  InputError(std::string file, std::string place, std::string problem)
      : std::runtime_error(compose(file, place, problem)),
        file_(std::move(file)),
        place_(std::move(place)),
        problem_(std::move(problem)) {}

  const std::string& file() const { return file_; }
  const std::string& place() const { return place_; }
  const std::string& problem() const { return problem_; }

  // This error in `file` if it names none (errors raised where the file is not known, e.g. by
  // a planner's grid, get the file of the command that fed the input); otherwise unchanged.
  InputError inFile(const std::string& file) const;

 private:
  static std::string compose(const std::string& file, const std::string& place,
                             const std::string& problem);
  std::string file_, place_, problem_;
};

// `text` with control characters (bytes 0-31 and 127: NUL, escape sequences, newlines) shown
// as \xNN, so quoting a user's bytes in a message can neither cut it short (NUL), spread it
// over several lines nor drive the terminal. Other bytes (UTF-8 file names) stay as they are.
std::string printableText(const std::string& text);

// A short excerpt of a user's bytes for a message: at most `max_chars` of them, then "..." if
// there were more, in single quotes, with control bytes and bytes from 0x80 up shown as \xNN
// (a binary file's first line quoted whole would be a screenful of noise and could drive the
// terminal; a 1 MB value given on the command line would be a megabyte of message).
std::string quotedExcerpt(const std::string& text, std::size_t max_chars = 40);

// The place of a `--set KEY=VALUE` assignment in a message: "--set " and the assignment, cut
// after 80 characters ("..." then): an error must not echo a megabyte given as a value.
std::string setAssignmentPlace(const std::string& assignment);

}  // namespace cosim
