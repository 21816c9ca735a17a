#pragma once
// The gains a flight controller declares, as OMPL's planners declare their parameters: each with
// its key under `controller.gains`, its default (the gains struct's member initialiser, read from
// a default-constructed struct, so it cannot drift from what the controller uses), its valid range
// and one line on what it does. A controller's GainTable both reads its gains and lists them:
// `cosim run --list-controllers`, docs/controllers.md (checked against it by
// tests/control/controller_registry_test.cpp) and the misspelt-gain message all come from it.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "control/gain_reading.h"
#include "core/param_set.h"

namespace cosim {

// The keys one declaration stands for: one gain, or a pair where the vehicle's symmetry about z
// lets axes share a gain (control/gain_reading.h).
enum class GainAxes {
  Single,           // <name>
  HorizontalAndZ,   // <name>_xy (x and y), <name>_z
  RollPitchAndYaw,  // <name>_rp (roll and pitch), <name>_yaw
};

struct GainDeclaration {
  std::string name;
  GainAxes axes = GainAxes::Single;
  // The default: x (for a pair: the shared gain's) and z (a pair's second gain).
  Eigen::Vector3d default_value = Eigen::Vector3d::Zero();
  double lo = 0.0, hi = 0.0;  // valid range, inclusive
  std::string doc;            // what it does, in its unit
  // Not empty: the gain is optional and its absence means this (e.g. "the airframe's mass");
  // a value given must then be in [lo, hi].
  std::string absent_means;
};

// One key of `controller.gains`, as the listing and the docs show it.
struct GainKey {
  std::string key;           // e.g. "att_kp_rp"
  std::string default_text;  // "7", as ParamSet shows values, or the declaration's absent_means
  std::string range_text;    // "[0, 10000]"
  std::string doc;           // the declaration's, with the axes a pair's key sets
};

// The keys of `declared`, in order (a pair gives two).
std::vector<GainKey> gainKeys(const std::vector<GainDeclaration>& declared);

// A controller's gains struct `Gains` with its declarations: `read` fills a Gains from the
// scenario's gains (each optional, each checked against its range), `declarations` lists them.
template <class Gains>
class GainTable {
 public:
  // One gain in [lo, hi].
  GainTable& gain(const std::string& name, double Gains::*member, double lo, double hi,
                  const std::string& doc) {
    return add({name, GainAxes::Single, {Gains{}.*member, 0.0, 0.0}, lo, hi, doc, ""}, member);
  }
  // <name>_xy and <name>_z, each in [0, hi] (readHorizontalAndZ).
  GainTable& horizontalAndZ(const std::string& name, Eigen::Vector3d Gains::*member, double hi,
                            const std::string& doc) {
    return add({name, GainAxes::HorizontalAndZ, Gains{}.*member, 0.0, hi, doc, ""}, member);
  }
  // <name>_rp and <name>_yaw, each in [0, hi] (readRollPitchAndYaw).
  GainTable& rollPitchAndYaw(const std::string& name, Eigen::Vector3d Gains::*member, double hi,
                             const std::string& doc) {
    return add({name, GainAxes::RollPitchAndYaw, Gains{}.*member, 0.0, hi, doc, ""}, member);
  }
  // A gain whose absence leaves the member at its initialiser, which means `absent_means`.
  GainTable& optionalGain(const std::string& name, double Gains::*member, double lo, double hi,
                          const std::string& doc, const std::string& absent_means) {
    return add({name, GainAxes::Single, {Gains{}.*member, 0.0, 0.0}, lo, hi, doc, absent_means},
               member);
  }

  // The gains `p` sets, the defaults for the rest. Throws InputError for a value out of range;
  // names `p` holds but no declaration reads are left for the caller's requireAllUsed.
  Gains read(ParamSet& p) const {
    Gains g;
    for (const Row& row : rows_) {
      const GainDeclaration& d = row.declaration;
      if (d.axes == GainAxes::HorizontalAndZ)
        g.*row.vector = readHorizontalAndZ(p, d.name, g.*row.vector, d.hi);
      else if (d.axes == GainAxes::RollPitchAndYaw)
        g.*row.vector = readRollPitchAndYaw(p, d.name, g.*row.vector, d.hi);
      else if (d.absent_means.empty() || p.has(d.name))
        g.*row.scalar = p.getDouble(d.name, g.*row.scalar, d.lo, d.hi);
    }
    return g;
  }

  std::vector<GainDeclaration> declarations() const {
    std::vector<GainDeclaration> out;
    for (const Row& row : rows_) out.push_back(row.declaration);
    return out;
  }

 private:
  struct Row {
    GainDeclaration declaration;
    double Gains::*scalar = nullptr;
    Eigen::Vector3d Gains::*vector = nullptr;
  };
  GainTable& add(GainDeclaration d, double Gains::*member) {
    rows_.push_back({std::move(d), member, nullptr});
    return *this;
  }
  GainTable& add(GainDeclaration d, Eigen::Vector3d Gains::*member) {
    rows_.push_back({std::move(d), nullptr, member});
    return *this;
  }

  std::vector<Row> rows_;
};

}  // namespace cosim
