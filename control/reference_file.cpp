#include "control/reference_file.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <vector>

#include "control/sampled_reference.h"
#include "core/decimal_text.h"
#include "core/input_error.h"
#include "core/input_file.h"

namespace cosim {

namespace {

// Coordinates, coefficients and times beyond this are surely a wrong file (a world is at most
// 10 km across), and keeping them finite keeps every polynomial finite over a day.
constexpr double kMaxMagnitude = 1e9;
// The shortest piece or sample interval: a microsecond (MuJoCo's smallest sensible step is ten).
constexpr double kMinInterval = 1e-6;

const char* const kPolynomialHeaderText =
    "duration,x^0,...,x^7,y^0,...,y^7,z^0,...,z^7,yaw^0,...,yaw^7";

std::string trimmed(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

// The line's fields, trimmed; one trailing comma ends the line without a field after it.
std::vector<std::string> splitFields(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream in(trimmed(line));
  for (std::string f; std::getline(in, f, ',');) out.push_back(trimmed(f));
  return out;
}

std::vector<std::string> polynomialHeader() {
  std::vector<std::string> h{"duration"};
  for (const char* axis : {"x", "y", "z", "yaw"})
    for (int k = 0; k < ReferencePiece::kCoefficients; ++k)
      h.push_back(std::string(axis) + "^" + std::to_string(k));
  return h;
}

// A user's field in a message: quoted, at most 40 characters, control and non-ASCII bytes
// escaped (the file named may be any readable file, binary or not).
std::string shown(const std::string& field) {
  return quotedExcerpt(field, 40);
}

std::string numberText(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

std::string place(std::size_t line, const std::string& column = "") {
  return "line " + std::to_string(line) + (column.empty() ? "" : ", column " + column);
}

double number(const std::string& field, const std::string& file, std::size_t line,
              const std::string& column) {
  if (field.empty()) throw InputError(file, place(line, column), "empty value");
  // strtod alone would take "0x10" as 16 and "inf" or "nan" as numbers.
  if (!isDecimalNumberText(field))
    throw InputError(file, place(line, column),
                     shown(field) + " is not a decimal number (such as 1.5 or -2e-3)");
  const double v = std::strtod(field.c_str(), nullptr);
  if (!std::isfinite(v))  // an overflow is inf; an underflow (ERANGE too) is a fine 0
    throw InputError(file, place(line, column), shown(field) + " is not a finite number");
  if (std::abs(v) > kMaxMagnitude)
    throw InputError(file, place(line, column), shown(field) + " is beyond +-1e9");
  return v;
}

// The file's non-blank lines with their 1-based line numbers.
struct Line {
  std::size_t number;
  std::string text;
};

std::vector<Line> nonBlankLines(const std::string& text) {
  std::vector<Line> lines;
  std::size_t number = 0, at = 0;
  while (at < text.size()) {
    const auto end = text.find('\n', at);
    std::string line = text.substr(at, end == std::string::npos ? std::string::npos : end - at);
    ++number;
    if (!trimmed(line).empty()) lines.push_back({number, std::move(line)});
    if (end == std::string::npos) break;
    at = end + 1;
  }
  return lines;
}

// The header's format, or an InputError saying what was expected.
ReferenceFormat headerFormat(const std::vector<std::string>& h, const std::string& file,
                             std::size_t line) {
  if (h.front() == "duration") {
    const std::vector<std::string> expected = polynomialHeader();
    if (h.size() != expected.size())
      throw InputError(file, place(line),
                       "header has " + std::to_string(h.size()) + " columns, expected " +
                           std::to_string(expected.size()) + " (" + kPolynomialHeaderText + ")");
    for (std::size_t i = 0; i < h.size(); ++i)
      if (h[i] != expected[i])
        throw InputError(file, place(line, std::to_string(i + 1)),
                         "header " + shown(h[i]) + " where '" + expected[i] + "' was expected");
    return ReferenceFormat::PolynomialPieces;
  }
  const std::vector<std::string> samples{"t", "x", "y", "z", "yaw"};
  bool sampled = h.size() == 4 || h.size() == 5;
  for (std::size_t i = 0; sampled && i < h.size(); ++i) sampled = h[i] == samples[i];
  if (sampled) return ReferenceFormat::Samples;
  std::string joined;
  for (const auto& f : h) joined += (joined.empty() ? "" : ",") + f;
  throw InputError(file, place(line),
                   "unknown header " + shown(joined) + ": expected '" + kPolynomialHeaderText +
                       "' (polynomial pieces) or 't,x,y,z' with an optional 'yaw' (samples)");
}

// One row's numbers, checked against the header's column count.
std::vector<double> rowValues(const Line& l, const std::vector<std::string>& header,
                              const std::string& file) {
  const std::vector<std::string> f = splitFields(l.text);
  if (f.size() != header.size())
    throw InputError(file, place(l.number),
                     std::to_string(f.size()) + " values, expected " +
                         std::to_string(header.size()) + " (as the header)");
  std::vector<double> v(f.size());
  for (std::size_t i = 0; i < f.size(); ++i) v[i] = number(f[i], file, l.number, header[i]);
  return v;
}

ReferencePiece pieceOf(const std::vector<double>& v, const Line& l, const std::string& file) {
  ReferencePiece p;
  p.duration = v[0];
  if (!(p.duration >= kMinInterval))
    throw InputError(file, place(l.number, "duration"),
                     "duration " + numberText(p.duration) + " s is not > 0 (at least 1e-6 s)");
  for (int axis = 0; axis < 4; ++axis)
    for (int k = 0; k < ReferencePiece::kCoefficients; ++k)
      p.coefficients(k, axis) = v[1 + axis * ReferencePiece::kCoefficients + k];
  return p;
}

ReferenceSample sampleOf(const std::vector<double>& v, const Line& l, const std::string& file,
                         const std::vector<ReferenceSample>& before) {
  ReferenceSample s{v[0], {v[1], v[2], v[3]}, v.size() > 4 ? v[4] : 0.0};
  if (!before.empty() && !(s.t - before.back().t >= kMinInterval))
    throw InputError(file, place(l.number, "t"),
                     "time " + numberText(s.t) + " is not after the previous row's " +
                         numberText(before.back().t) +
                         " (times must increase, by at least 1e-6 s)");
  return s;
}

}  // namespace

const char* referenceFormatName(ReferenceFormat format) {
  return format == ReferenceFormat::Samples ? "samples" : "polynomial pieces";
}

ReferenceFile parseReferenceText(const std::string& text, const std::string& file) {
  const std::vector<Line> lines = nonBlankLines(text);
  if (lines.empty())
    throw InputError(file, "line 1",
                     std::string("empty file: expected a header, '") + kPolynomialHeaderText +
                         "' (polynomial pieces) or 't,x,y,z[,yaw]' (samples)");
  const std::vector<std::string> header = splitFields(lines.front().text);
  const ReferenceFormat format = headerFormat(header, file, lines.front().number);
  const bool sampled = format == ReferenceFormat::Samples;
  std::vector<ReferencePiece> pieces;
  std::vector<ReferenceSample> samples;
  double duration = 0.0;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const Line& l = lines[i];
    if (i > kMaxReferencePieces + (sampled ? 1 : 0))
      throw InputError(file, place(l.number),
                       "more than " + std::to_string(kMaxReferencePieces) +
                           (sampled ? " intervals between samples" : " pieces"));
    const std::vector<double> v = rowValues(l, header, file);
    if (sampled) {
      samples.push_back(sampleOf(v, l, file, samples));
      duration = samples.back().t - samples.front().t;
    } else {
      pieces.push_back(pieceOf(v, l, file));
      duration += pieces.back().duration;
    }
    if (duration > kMaxReferenceDuration)
      throw InputError(file, place(l.number),
                       "the reference lasts more than a day (86400 s) by this row");
  }
  const std::size_t last = lines.back().number;
  if (sampled && samples.size() < 2)
    throw InputError(file, place(last), "a sampled reference needs at least two rows");
  if (!sampled && pieces.empty()) throw InputError(file, place(last), "no pieces after the header");
  if (sampled) return {format, SampledReference(samples)};
  return {format, PiecewisePolynomialReference(std::move(pieces))};
}

ReferenceFile readReferenceFile(const std::string& path) {
  return parseReferenceText(readInputFile(path, kMaxReferenceFileBytes, "reference file"), path);
}

}  // namespace cosim
