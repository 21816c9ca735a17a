#include "sim/urdf_file.h"

#include <console_bridge/console.h>
#include <tinyxml2.h>
#include <urdf_parser/urdf_parser.h>

#include <cstring>
#include <map>
#include <vector>

#include "core/input_error.h"
#include "core/input_file.h"
#include "sim/urdf_vehicle.h"

namespace cosim {

namespace {

using tinyxml2::XMLDocument;
using tinyxml2::XMLElement;

// A ground robot's number of links at most (a design value, far above real robots: a mobile
// manipulator has about 30).
constexpr std::size_t kMaxUrdfLinks = 1000;

// Collects urdfdom's console messages during a parse, so that its complaint becomes the text of
// one InputError instead of lines on stderr.
class ParseMessages : public console_bridge::OutputHandler {
 public:
  ParseMessages() { console_bridge::useOutputHandler(this); }
  ~ParseMessages() override { console_bridge::restorePreviousOutputHandler(); }
  void log(const std::string& text, console_bridge::LogLevel level, const char*, int) override {
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_ERROR && first_error.empty())
      first_error = text;
  }
  std::string first_error;
};

// The joints must make a tree: urdfdom links each child to its parent with shared pointers, so a
// loop of joints (a -> b -> a) leaves a cycle of them behind when it then rejects the robot (a
// leak the fuzzer found). Checked here on the XML, iteratively (no recursion the input controls).
void checkJointGraph(const XMLDocument& xml, const std::string& file) {
  const XMLElement* robot = xml.FirstChildElement("robot");
  if (!robot) return;  // urdfdom names that problem
  std::map<std::string, std::string> parent_of;  // child link -> parent link
  for (const XMLElement* j = robot->FirstChildElement("joint"); j;
       j = j->NextSiblingElement("joint")) {
    const XMLElement* parent = j->FirstChildElement("parent");
    const XMLElement* child = j->FirstChildElement("child");
    const char* p = parent ? parent->Attribute("link") : nullptr;
    const char* c = child ? child->Attribute("link") : nullptr;
    if (!p || !c) continue;  // urdfdom names that problem
    const std::string where = "line " + std::to_string(j->GetLineNum()) + ", <joint>";
    if (!parent_of.emplace(c, p).second)
      throw InputError(file, where,
                       std::string("link '") + c + "' is the child of two joints (a kinematic "
                                                   "loop; a URDF robot is a tree)");
    // Walk up from the new joint's parent: reaching its child closes a loop. The walk ends within
    // the number of joints, since every earlier joint kept the graph a forest.
    for (auto it = parent_of.find(p); it != parent_of.end(); it = parent_of.find(it->second))
      if (it->first == c || it->second == c)
        throw InputError(file, where,
                         std::string("link '") + c + "' is its own ancestor (the joints form a "
                                                     "loop; a URDF robot is a tree)");
  }
}

}  // namespace

urdf::ModelInterfaceSharedPtr parseUrdf(const std::string& file) {
  const std::string text = readInputFile(file, kMaxModelFileBytes, "URDF file");
  // tinyxml2 first: it reports XML syntax errors with a line number, urdfdom does not.
  XMLDocument xml;
  if (xml.Parse(text.data(), text.size()) != tinyxml2::XML_SUCCESS)
    throw InputError(file, "line " + std::to_string(xml.ErrorLineNum()),
                     std::string("malformed XML: ") + xml.ErrorName());
  // Counted before urdfdom builds anything: a robot of thousands of links is a mistake that would
  // cost seconds and gigabytes in urdfdom and MuJoCo's compiler.
  if (const XMLElement* robot = xml.FirstChildElement("robot")) {
    std::size_t links = 0;
    for (const XMLElement* l = robot->FirstChildElement("link"); l;
         l = l->NextSiblingElement("link"))
      if (++links > kMaxUrdfLinks)
        throw InputError(file, "line " + std::to_string(l->GetLineNum()) + ", <link>",
                         "more than " + std::to_string(kMaxUrdfLinks) +
                             " links (a ground robot has a few dozen at most)");
  }
  checkJointGraph(xml, file);
  ParseMessages messages;
  urdf::ModelInterfaceSharedPtr model = urdf::parseURDF(text);
  if (!model)
    throw InputError(
        file, "<robot>",
        "malformed URDF: " + (messages.first_error.empty() ? std::string("rejected by urdfdom")
                                                           : messages.first_error));
  return model;
}

std::filesystem::path meshPath(const std::string& filename, const std::filesystem::path& dir) {
  if (filename.rfind("package://", 0) == 0) return {};
  const std::string name = filename.rfind("file://", 0) == 0 ? filename.substr(7) : filename;
  const std::filesystem::path path(name);
  return path.is_relative() ? dir / path : path;
}

std::vector<std::filesystem::path> urdfMeshFiles(const std::filesystem::path& urdf) {
  std::vector<std::filesystem::path> files;
  XMLDocument xml;
  try {
    const std::string text = readInputFile(urdf.string(), kMaxModelFileBytes, "URDF file");
    if (xml.Parse(text.data(), text.size()) != tinyxml2::XML_SUCCESS) return files;
  } catch (const InputError&) {
    return files;
  }
  std::vector<const XMLElement*> open = {xml.RootElement()};
  while (!open.empty() && open.back()) {
    const XMLElement* e = open.back();
    open.pop_back();
    if (const char* f = e->Attribute("filename"); f && std::strcmp(e->Name(), "mesh") == 0)
      if (const auto p = meshPath(f, urdf.parent_path()); !p.empty()) files.push_back(p);
    for (const XMLElement* c = e->FirstChildElement(); c; c = c->NextSiblingElement())
      open.push_back(c);
  }
  return files;
}

}  // namespace cosim
