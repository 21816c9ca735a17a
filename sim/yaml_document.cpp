#include "sim/yaml_document.h"

#include <yaml-cpp/eventhandler.h>

#include <set>
#include <sstream>
#include <vector>

#include "core/input_error.h"

namespace cosim {

namespace {

// One container on the path from the root to the node being looked at.
struct Frame {
  YAML::Node node;
  std::string key;  // how the parent names it: "world", "[3]"
  YAML::const_iterator next, end;
  std::size_t index = 0;            // sequences: the next element's index
  std::set<std::string> keys_seen;  // mappings: the keys so far
};

std::string keyPath(const std::vector<Frame>& path, const std::string& last) {
  std::string s;
  for (const Frame& f : path) {
    if (f.key.empty()) continue;
    if (!s.empty() && f.key.front() != '[') s += '.';
    s += f.key;
  }
  if (!last.empty()) {
    if (!s.empty() && last.front() != '[') s += '.';
    s += last;
  }
  return s.empty() ? "(document)" : s;
}

[[noreturn]] void fail(const std::string& file, const YAML::Node& at, const std::string& key,
                       const std::string& problem) {
  const YAML::Mark mark = at.Mark();
  std::string place =
      mark.is_null() || mark.line < 0 ? std::string() : "line " + std::to_string(mark.line + 1);
  place += (place.empty() ? "key " : ", key ") + key;
  throw InputError(file, place, problem);
}

// Counts the values of a document as the parser reads it, building nothing: yaml-cpp's nodes
// cost about 470 bytes each (a million took 470 MB here), so a large document is refused before
// they exist. Aliases count once here; their expansion is counted by checkYamlStructure.
class ValueCounter : public YAML::EventHandler {
 public:
  struct TooMany {
    YAML::Mark mark;
  };
  void OnDocumentStart(const YAML::Mark&) override {}
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark& m, YAML::anchor_t) override { count(m); }
  void OnAlias(const YAML::Mark& m, YAML::anchor_t) override { count(m); }
  void OnScalar(const YAML::Mark& m, const std::string&, YAML::anchor_t,
                const std::string&) override {
    count(m);
  }
  void OnSequenceStart(const YAML::Mark& m, const std::string&, YAML::anchor_t,
                       YAML::EmitterStyle::value) override {
    count(m);
  }
  void OnSequenceEnd() override {}
  void OnMapStart(const YAML::Mark& m, const std::string&, YAML::anchor_t,
                  YAML::EmitterStyle::value) override {
    count(m);
  }
  void OnMapEnd() override {}

 private:
  void count(const YAML::Mark& m) {
    if (++values_ > kMaxYamlValues) throw TooMany{m};
  }
  std::size_t values_ = 0;
};

// Stops the parser at the start of a second document ("---" after the first), building nothing.
class SecondDocument : public YAML::EventHandler {
 public:
  struct Found {
    YAML::Mark mark;
  };
  void OnDocumentStart(const YAML::Mark& m) override { throw Found{m}; }
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark&, YAML::anchor_t) override {}
  void OnAlias(const YAML::Mark&, YAML::anchor_t) override {}
  void OnScalar(const YAML::Mark&, const std::string&, YAML::anchor_t,
                const std::string&) override {}
  void OnSequenceStart(const YAML::Mark&, const std::string&, YAML::anchor_t,
                       YAML::EmitterStyle::value) override {}
  void OnSequenceEnd() override {}
  void OnMapStart(const YAML::Mark&, const std::string&, YAML::anchor_t,
                  YAML::EmitterStyle::value) override {}
  void OnMapEnd() override {}
};

std::string tooManyValues() {
  return "the document holds more than " + std::to_string(kMaxYamlValues) +
         " values once its aliases are expanded (each use of an alias counts)";
}

}  // namespace

YAML::Node loadYamlDocument(const std::string& text, const std::string& file) {
  YAML::Node root;
  try {
    {
      std::istringstream in(text);
      YAML::Parser parser(in);
      ValueCounter counter;
      parser.HandleNextDocument(counter);
      // yaml-cpp's Load reads the first document only: a second one would be silently ignored.
      SecondDocument second;
      parser.HandleNextDocument(second);
    }
    root = YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    throw InputError(file, "line " + std::to_string(e.mark.line + 1), "malformed YAML: " + e.msg);
  } catch (const ValueCounter::TooMany& e) {
    throw InputError(file, "line " + std::to_string(e.mark.line + 1), tooManyValues());
  } catch (const SecondDocument::Found& e) {
    throw InputError(file, "line " + std::to_string(e.mark.line + 1),
                     "a second YAML document (after '---'): a file holds one document; its "
                     "contents would be ignored");
  }
  checkYamlStructure(root, file);
  return root;
}

void checkYamlStructure(const YAML::Node& root, const std::string& file) {
  std::size_t values = 0;
  std::vector<Frame> path;
  // Visits `node` (named `key` by its parent): counts it and, if it is a container, descends.
  const auto visit = [&](const YAML::Node& node, const std::string& key) {
    if (++values > kMaxYamlValues) fail(file, node, keyPath(path, key), tooManyValues());
    if (!node.IsMap() && !node.IsSequence()) return;
    for (const Frame& f : path)
      if (f.node.is(node))
        fail(file, node, keyPath(path, key),
             "an alias refers to a node that contains it (a cycle: the value would be infinite)");
    if (static_cast<int>(path.size()) >= kMaxYamlDepth)
      fail(file, node, keyPath(path, key),
           "nested more than " + std::to_string(kMaxYamlDepth) + " levels deep");
    path.push_back(Frame{node, key, node.begin(), node.end(), 0, {}});
  };
  visit(root, "");
  while (!path.empty()) {
    Frame& top = path.back();
    if (top.next == top.end) {
      path.pop_back();
      continue;
    }
    const auto child = *top.next;
    ++top.next;
    // `top` is not used after visit(), which may grow `path`.
    if (top.node.IsSequence()) {
      // Built piecewise: GCC 12 warns falsely (-Wrestrict) on "[" + std::string temporary.
      std::string index = std::to_string(top.index++);
      index.insert(index.begin(), '[');
      visit(child, index + "]");
      continue;
    }
    const YAML::Node key = child.first;
    if (!key.IsScalar())
      fail(file, key, keyPath(path, ""), "a key must be a plain name, not a list or mapping");
    const std::string name = key.Scalar();
    if (!top.keys_seen.insert(name).second)
      fail(file, key, keyPath(path, name),
           "key '" + name + "' is given twice in this mapping (one of the values would be lost)");
    ++values;  // the key itself
    visit(child.second, name);
  }
}

}  // namespace cosim
