#pragma once
// Named planner (and controller) parameters, as OMPL declares them: a planner asks for each
// parameter by name with its default and valid range; whatever the user set but no one asked for
// is an error (a misspelt parameter must not be silently ignored).
#include <map>
#include <string>
#include <vector>

namespace cosim {

// What a consumer declared when it asked for a parameter: its type, default and valid values.
// A planner built from an empty ParamSet declares every parameter it reads, so the list of a
// planner's parameters (`cosim plan --list`) comes from the very calls that read them, with the
// defaults they really use.
struct ParamDeclaration {
  std::string name;
  std::string type;           // "number", "integer", "bool" or "text"
  std::string default_value;  // as effective() would show it
  std::string range;          // "[0.01, 100]", ">= 1", "true|false", "fixed|dynamic", "any"
};

// A number as a ParamSet shows it (12 significant digits), and a number's valid range as its
// declaration does ("[lo, hi]", ">= lo", "<= hi", "any"): for lists of parameters declared
// elsewhere (a controller's gains) to read as the planners' do.
std::string paramNumberText(double v);
std::string paramNumberRangeText(double lo, double hi);

class ParamSet {
 public:
  ParamSet() = default;
  // file: where the values came from, for error messages (scenario path or "command line").
  explicit ParamSet(std::string file) : file_(std::move(file)) {}

  // Sets a raw value; place is e.g. "line 12, key planner.resolution".
  void set(const std::string& name, const std::string& value, const std::string& place = "");
  bool has(const std::string& name) const { return values_.count(name) != 0; }
  // The names set (not those only asked for), in name order.
  std::vector<std::string> names() const;
  // A copy without the values of `names` (as if they had never been set).
  ParamSet without(const std::vector<std::string>& names) const;

  double getDouble(const std::string& name, double fallback, double lo = -1e300, double hi = 1e300);
  int getInt(const std::string& name, int fallback, int lo = -2147483647, int hi = 2147483647);
  bool getBool(const std::string& name, bool fallback);
  std::string getString(const std::string& name, const std::string& fallback,
                        const std::vector<std::string>& allowed = {});

  // Throws InputError naming the first parameter that was set but never asked for.
  // `owner` names the consumer in the message, e.g. "planner 'astar'".
  void requireAllUsed(const std::string& owner) const;
  // As requireAllUsed, but parameters named in `tolerated` are not errors: they are returned
  // (for a note to the user) instead.
  std::vector<std::string> requireAllUsedExcept(const std::string& owner,
                                                const std::vector<std::string>& tolerated) const;
  // As requireAllUsed, but a parameter that other consumers take is named as theirs: `others`
  // maps such a name to who takes it ("planners rrt, rrt_star"), and the message says that it
  // does not apply to `owner` and lists what `owner` takes.
  void requireAllUsed(const std::string& owner,
                      const std::map<std::string, std::string>& others) const;

  // Every parameter asked for, with the value in force (set or default), for plan.json.
  const std::map<std::string, std::string>& effective() const { return effective_; }
  // Every parameter asked for, in the order first asked, as declared by that first ask.
  const std::vector<ParamDeclaration>& declarations() const { return declarations_; }
  const std::string& file() const { return file_; }

 private:
  struct Entry {
    std::string value;
    std::string place;
  };
  [[noreturn]] void fail(const std::string& name, const std::string& problem) const;
  const Entry* find(const std::string& name);
  void declare(ParamDeclaration declaration);

  std::string file_;
  std::map<std::string, Entry> values_;
  std::map<std::string, bool> used_;
  std::map<std::string, std::string> effective_;
  std::vector<ParamDeclaration> declarations_;
};

}  // namespace cosim
