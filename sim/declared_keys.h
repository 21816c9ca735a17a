#pragma once
// One declaration per scenario setting. Each settings struct declares its keys once, next to
// its fields, in a member template
//
//   template <class Visitor> void declareKeys(Visitor& v) {
//     v.number("timestep", timestep, 1e-5, 0.02, "s, the physics step");
//     v.choice("fuse", fix_timing, kFixTimingNames, "when a late fix is fused");
//   }
//
// (name, the member, whose initialiser is the default, its range, one line of doc), and visitors
// walk that one declaration: DeclaredKeyNames (below) for the section's key list (unknown keys
// and their did-you-mean), DeclaredKeyReader (sim/declared_key_reader.h) to read a YAML section
// with located, type- and range-checked messages, and DeclaredKeyDocs (sim/declared_key_docs.h)
// for docs/scenario_keys.md. A key read by code of its own (a list of blocks, a file) is declared
// with v.custom(name, type, doc): listed and documented, read by its section's reader.
//
// The visitor methods (every visitor has them all):
//   number(name, double&, lo, hi, doc)          a number in [lo, hi]
//   integer(name, int or uint64&, lo, hi, doc)  a whole number in [lo, hi]
//   boolean(name, bool&, doc)                   true or false
//   text(name, std::string&, doc)               a non-empty word (checked by its user)
//   vec3(name, Eigen::Vector3d&, lo, hi, doc)   [x, y, z], each component in [lo, hi]
//   choice(name, E&, names, doc)                one of an enum's declared names
//   choices(name, std::vector<E>&, names, doc)  a list of them
//   custom(name, type, doc)                     read by the section's own code
#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace cosim {

// The name a scenario writes for one value of a choice key's enum; an enum declares the whole
// list once, as a constexpr array of these, and everything else asks that list.
template <class E>
struct ChoiceName {
  E value;
  const char* name;
};

template <class E, std::size_t N>
using ChoiceNames = std::array<ChoiceName<E>, N>;

// The name of `value` in `names` ("" if it is not declared).
template <class E, std::size_t N>
const char* choiceName(const ChoiceNames<E, N>& names, E value) {
  for (const auto& c : names)
    if (c.value == value) return c.name;
  return "";
}

// The value named `name`, or nullopt.
template <class E, std::size_t N>
std::optional<E> choiceNamed(const ChoiceNames<E, N>& names, const std::string& name) {
  for (const auto& c : names)
    if (name == c.name) return c.value;
  return std::nullopt;
}

// "'a', 'b' or 'c'": the allowed names, for messages.
template <class E, std::size_t N>
std::string choiceList(const ChoiceNames<E, N>& names) {
  std::string list;
  for (std::size_t i = 0; i < N; ++i)
    list += std::string(i == 0 ? "" : i + 1 == N ? " or " : ", ") + "'" + names[i].name + "'";
  return list;
}

// The names a section declares, in declaration order: what checkKeys allows there.
class DeclaredKeyNames {
 public:
  const std::vector<std::string>& names() const { return names_; }

  template <class T>
  void number(const char* name, T&, double, double, const char*) {
    names_.push_back(name);
  }
  template <class T>
  void integer(const char* name, T&, long, long, const char*) {
    names_.push_back(name);
  }
  template <class T>
  void vec3(const char* name, T&, double, double, const char*) {
    names_.push_back(name);
  }
  void boolean(const char* name, bool&, const char*) { names_.push_back(name); }
  void text(const char* name, std::string&, const char*) { names_.push_back(name); }
  template <class E, class Names>
  void choice(const char* name, E&, const Names&, const char*) {
    names_.push_back(name);
  }
  template <class E, class Names>
  void choices(const char* name, std::vector<E>&, const Names&, const char*) {
    names_.push_back(name);
  }
  void custom(const char* name, const char*, const char*) { names_.push_back(name); }

 private:
  std::vector<std::string> names_;
};

// The key names `settings` declares.
template <class Settings>
std::vector<std::string> declaredKeyNames(Settings& settings) {
  DeclaredKeyNames names;
  settings.declareKeys(names);
  return names.names();
}

}  // namespace cosim
