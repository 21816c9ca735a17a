#include "core/param_set.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "core/input_error.h"
#include "core/name_suggestion.h"

namespace cosim {

namespace {
std::string formatNumber(double v) {
  std::ostringstream out;
  out.precision(12);
  out << v;
  return out.str();
}

// "[lo, hi]", ">= lo", "<= hi" or "any": a bound at the type's extreme (the getters' defaults)
// is no bound.
template <class T>
std::string rangeText(T lo, T hi, T lowest, T highest, std::string (*format)(T)) {
  // (appended piecewise: GCC 12 warns falsely on "..." + std::string, -Wrestrict)
  std::string text;
  if (lo <= lowest && hi >= highest) return "any";
  if (hi >= highest) return text.append(">= ").append(format(lo));
  if (lo <= lowest) return text.append("<= ").append(format(hi));
  return text.append("[").append(format(lo)).append(", ").append(format(hi)).append("]");
}
std::string formatInt(long v) {
  return std::to_string(v);
}
}  // namespace

std::string paramNumberText(double v) {
  return formatNumber(v);
}

std::string paramNumberRangeText(double lo, double hi) {
  return rangeText(lo, hi, -1e300, 1e300, formatNumber);
}

void ParamSet::declare(ParamDeclaration declaration) {
  for (const ParamDeclaration& d : declarations_)
    if (d.name == declaration.name) return;  // the first ask declares it
  declarations_.push_back(std::move(declaration));
}

void ParamSet::set(const std::string& name, const std::string& value, const std::string& place) {
  values_[name] = Entry{value, place};
}

std::vector<std::string> ParamSet::names() const {
  std::vector<std::string> out;
  for (const auto& [name, entry] : values_) out.push_back(name);
  return out;
}

ParamSet ParamSet::without(const std::vector<std::string>& names) const {
  ParamSet copy(file_);
  for (const auto& [name, entry] : values_)
    if (std::find(names.begin(), names.end(), name) == names.end())
      copy.set(name, entry.value, entry.place);
  return copy;
}

void ParamSet::fail(const std::string& name, const std::string& problem) const {
  auto it = values_.find(name);
  std::string place =
      (it != values_.end() && !it->second.place.empty()) ? it->second.place : "parameter " + name;
  throw InputError(file_, place, problem);
}

const ParamSet::Entry* ParamSet::find(const std::string& name) {
  used_[name] = true;
  auto it = values_.find(name);
  return it == values_.end() ? nullptr : &it->second;
}

double ParamSet::getDouble(const std::string& name, double fallback, double lo, double hi) {
  declare({name, "number", formatNumber(fallback), paramNumberRangeText(lo, hi)});
  double v = fallback;
  if (const Entry* e = find(name)) {
    char* end = nullptr;
    v = std::strtod(e->value.c_str(), &end);
    if (e->value.empty() || end == e->value.c_str() || *end != '\0' || !std::isfinite(v))
      fail(name, "'" + name + "' must be a number, got " + quotedExcerpt(e->value, 80));
  }
  if (v < lo || v > hi)
    fail(name, "'" + name + "' = " + formatNumber(v) + " is outside [" + formatNumber(lo) + ", " +
                   formatNumber(hi) + "]");
  effective_[name] = formatNumber(v);
  return v;
}

int ParamSet::getInt(const std::string& name, int fallback, int lo, int hi) {
  declare({name, "integer", std::to_string(fallback),
           rangeText<long>(lo, hi, -2147483647L, 2147483647L, formatInt)});
  long v = fallback;
  if (const Entry* e = find(name)) {
    char* end = nullptr;
    v = std::strtol(e->value.c_str(), &end, 10);
    if (e->value.empty() || *end != '\0' || v > 2147483647L || v < -2147483647L)
      fail(name, "'" + name + "' must be a whole number, got " + quotedExcerpt(e->value, 80));
  }
  if (v < lo || v > hi)
    fail(name, "'" + name + "' = " + std::to_string(v) + " is outside [" + std::to_string(lo) +
                   ", " + std::to_string(hi) + "]");
  effective_[name] = std::to_string(v);
  return static_cast<int>(v);
}

bool ParamSet::getBool(const std::string& name, bool fallback) {
  declare({name, "bool", fallback ? "true" : "false", "true|false"});
  bool v = fallback;
  if (const Entry* e = find(name)) {
    std::string s = e->value;
    std::transform(s.begin(), s.end(), s.begin(), ::tolower);
    if (s == "true" || s == "1" || s == "yes" || s == "on")
      v = true;
    else if (s == "false" || s == "0" || s == "no" || s == "off")
      v = false;
    else
      fail(name, "'" + name + "' must be true or false, got " + quotedExcerpt(e->value, 80));
  }
  effective_[name] = v ? "true" : "false";
  return v;
}

std::string ParamSet::getString(const std::string& name, const std::string& fallback,
                                const std::vector<std::string>& allowed) {
  std::string choices;
  for (const auto& a : allowed) choices += (choices.empty() ? "" : "|") + a;
  declare({name, "text", fallback, allowed.empty() ? "any" : choices});
  std::string v = fallback;
  if (const Entry* e = find(name)) v = e->value;
  if (!allowed.empty() && std::find(allowed.begin(), allowed.end(), v) == allowed.end()) {
    std::string list;
    for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
    fail(name, "'" + name + "' = " + quotedExcerpt(v, 80) + " is not one of: " + list);
  }
  effective_[name] = v;
  return v;
}

namespace {
// "unknown parameter 'x' for OWNER (did you mean 'y'? allowed: ...)": the allowed names are those
// the owner asked for.
std::string unknownParameterProblem(const std::string& name, const std::string& owner,
                                    const std::map<std::string, bool>& asked) {
  std::vector<std::string> names;
  std::string list;
  for (const auto& [known, used] : asked) {
    names.push_back(known);
    list += (list.empty() ? "" : ", ") + known;
  }
  const std::string hint = didYouMean(name, names);
  return "unknown parameter '" + name + "' for " + owner + " (" + (hint.empty() ? "" : hint + " ") +
         "allowed: " + (list.empty() ? "none" : list) + ")";
}
}  // namespace

std::vector<std::string> ParamSet::requireAllUsedExcept(
    const std::string& owner, const std::vector<std::string>& tolerated) const {
  std::vector<std::string> ignored;
  for (const auto& [name, entry] : values_) {
    if (used_.count(name)) continue;
    if (std::find(tolerated.begin(), tolerated.end(), name) == tolerated.end())
      fail(name, unknownParameterProblem(name, owner, used_));
    ignored.push_back(name);
  }
  return ignored;
}

void ParamSet::requireAllUsed(const std::string& owner,
                              const std::map<std::string, std::string>& others) const {
  for (const auto& [name, entry] : values_) {
    if (used_.count(name)) continue;
    const auto taker = others.find(name);
    if (taker == others.end()) fail(name, unknownParameterProblem(name, owner, used_));
    std::string list;
    for (const auto& [known, used] : used_) list += (list.empty() ? "" : ", ") + known;
    fail(name, "parameter '" + name + "' does not apply to " + owner + " (it is a parameter of " +
                   taker->second + "; " + owner + " takes: " + (list.empty() ? "none" : list) +
                   ")");
  }
}

void ParamSet::requireAllUsed(const std::string& owner) const {
  for (const auto& [name, entry] : values_) {
    if (!used_.count(name)) fail(name, unknownParameterProblem(name, owner, used_));
  }
}

}  // namespace cosim
