// libFuzzer target: a world fragment (world.include) as a run takes it: checked and spliced into
// a world by cosim::addWorldFragment, then compiled by MuJoCo. A fragment may be refused only with
// an InputError; one that passes the checks must compile (or fail to compile, with MuJoCo's
// message) without MuJoCo stopping the program or allocating without bound (a 200-byte fragment
// declaring a 38000 x 38000 height field took 5.6 GB).
#include <mujoco/mujoco.h>
#include <tinyxml2.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/input_error.h"
#include "sim/mujoco_messages.h"
#include "sim/world_fragment.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::filesystem::path file =
      std::filesystem::temp_directory_path() /
      ("cosim-fuzz-fragment-" + std::to_string(::getpid()) + ".xml");
  static const bool handlers = (cosim::installMujocoMessageHandlers(), true);
  (void)handlers;
  {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  tinyxml2::XMLDocument doc;
  tinyxml2::XMLElement* root = doc.NewElement("mujoco");
  doc.InsertEndChild(root);
  root->InsertNewChildElement("compiler")->SetAttribute("autolimits", "true");
  tinyxml2::XMLElement* floor =
      root->InsertNewChildElement("worldbody")->InsertNewChildElement("geom");
  floor->SetAttribute("name", "floor");
  floor->SetAttribute("type", "plane");
  floor->SetAttribute("size", "10 10 0.1");
  try {
    cosim::addWorldFragment(doc, root, file);
  } catch (const cosim::InputError&) {
    return 0;
  }
  tinyxml2::XMLPrinter printer;
  doc.Print(&printer);
  const std::string xml = printer.CStr();
  mjVFS vfs;
  mj_defaultVFS(&vfs);
  if (mj_makeEmptyFileVFS(&vfs, "world.xml", static_cast<int>(xml.size())) == 0) {
    std::memcpy(vfs.filedata[mj_findFileVFS(&vfs, "world.xml")], xml.data(), xml.size());
    char error[1024] = "";
    if (mjModel* m = mj_loadXML("world.xml", &vfs, error, sizeof error)) mj_deleteModel(m);
  }
  mj_deleteVFS(&vfs);
  return 0;
}
