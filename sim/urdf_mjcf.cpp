#include "sim/urdf_mjcf.h"

namespace cosim::urdf_mjcf {

using tinyxml2::XMLDocument;
using tinyxml2::XMLElement;

std::string fmt3(double a, double b, double c) {
  return tenSignificantDigits(a) + " " + tenSignificantDigits(b) + " " + tenSignificantDigits(c);
}

XMLElement* add(XMLDocument& doc, XMLElement* parent, const char* tag) {
  XMLElement* e = doc.NewElement(tag);
  parent->InsertEndChild(e);
  return e;
}

XMLElement* section(XMLDocument& doc, const char* tag) {
  XMLElement* root = doc.FirstChildElement("mujoco");
  XMLElement* e = root->FirstChildElement(tag);
  return e ? e : add(doc, root, tag);
}

Eigen::Vector3d vec(const urdf::Vector3& v) {
  return {v.x, v.y, v.z};
}
Eigen::Quaterniond quat(const urdf::Rotation& r) {
  return Eigen::Quaterniond(r.w, r.x, r.y, r.z);
}
Eigen::Isometry3d pose(const urdf::Pose& p) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = quat(p.rotation).normalized().toRotationMatrix();
  t.translation() = vec(p.position);
  return t;
}
void setPose(XMLElement* e, const urdf::Pose& p) {
  e->SetAttribute("pos", fmt3(p.position.x, p.position.y, p.position.z).c_str());
  const Eigen::Quaterniond q = quat(p.rotation).normalized();
  e->SetAttribute("quat", (tenSignificantDigits(q.w()) + " " + fmt3(q.x(), q.y(), q.z())).c_str());
}

}  // namespace cosim::urdf_mjcf
