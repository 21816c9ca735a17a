#include "render/colour_difference.h"

#include <cmath>

namespace cosim {

namespace {

constexpr double kPi = 3.14159265358979323846;

double degrees(double rad) {
  return rad * 180.0 / kPi;
}
double radians(double deg) {
  return deg * kPi / 180.0;
}

// IEC 61966-2-1: the sRGB transfer function inverted (gamma-encoded value to linear light).
double linearLight(double c) {
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

// CIE 15:2004, the L*a*b* companding of a tristimulus ratio.
double labCompand(double t) {
  constexpr double e = 216.0 / 24389.0, k = 24389.0 / 27.0;
  return t > e ? std::cbrt(t) : (k * t + 16.0) / 116.0;
}

// Sharma et al. equation 7: the hue angle in degrees, 0..360, and 0 for a neutral colour.
double hueAngle(double b, double a) {
  if (a == 0.0 && b == 0.0) return 0.0;
  const double h = degrees(std::atan2(b, a));
  return h < 0.0 ? h + 360.0 : h;
}

}  // namespace

Eigen::Vector3d srgbToLab(const Eigen::Vector3f& rgb) {
  const double r = linearLight(rgb.x()), g = linearLight(rgb.y()), b = linearLight(rgb.z());
  // IEC 61966-2-1's linear sRGB to XYZ matrix (D65).
  const double x = 0.4124 * r + 0.3576 * g + 0.1805 * b;
  const double y = 0.2126 * r + 0.7152 * g + 0.0722 * b;
  const double z = 0.0193 * r + 0.1192 * g + 0.9505 * b;
  const double fx = labCompand(x / 0.95047), fy = labCompand(y / 1.0), fz = labCompand(z / 1.08883);
  return {116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)};
}

double ciede2000(const Eigen::Vector3d& lab1, const Eigen::Vector3d& lab2) {
  const double L1 = lab1.x(), a1 = lab1.y(), b1 = lab1.z();
  const double L2 = lab2.x(), a2 = lab2.y(), b2 = lab2.z();
  // Equations 2-7: a* stretched by G so that near-neutral colours' hues weigh less.
  const double C1 = std::hypot(a1, b1), C2 = std::hypot(a2, b2);
  const double Cbar7 = std::pow(0.5 * (C1 + C2), 7.0);
  const double G = 0.5 * (1.0 - std::sqrt(Cbar7 / (Cbar7 + std::pow(25.0, 7.0))));
  const double a1p = (1.0 + G) * a1, a2p = (1.0 + G) * a2;
  const double C1p = std::hypot(a1p, b1), C2p = std::hypot(a2p, b2);
  const double h1p = hueAngle(b1, a1p), h2p = hueAngle(b2, a2p);
  // Equations 8-10: the differences; the hue difference is 0 when either colour is neutral.
  const double dLp = L2 - L1, dCp = C2p - C1p;
  double dhp = 0.0;
  if (C1p * C2p != 0.0) {
    dhp = h2p - h1p;
    if (dhp > 180.0) dhp -= 360.0;
    if (dhp < -180.0) dhp += 360.0;
  }
  const double dHp = 2.0 * std::sqrt(C1p * C2p) * std::sin(radians(0.5 * dhp));
  // Equations 12-14: the means; the mean hue across the 0/360 seam (equation 14's cases).
  const double Lbarp = 0.5 * (L1 + L2), Cbarp = 0.5 * (C1p + C2p);
  double hbarp = h1p + h2p;
  if (C1p * C2p != 0.0) {
    if (std::abs(h1p - h2p) <= 180.0)
      hbarp *= 0.5;
    else
      hbarp = hbarp < 360.0 ? 0.5 * (hbarp + 360.0) : 0.5 * (hbarp - 360.0);
  }
  // Equations 15-21: the weighting functions and the rotation term in the blue region.
  const double T =
      1.0 - 0.17 * std::cos(radians(hbarp - 30.0)) + 0.24 * std::cos(radians(2.0 * hbarp)) +
      0.32 * std::cos(radians(3.0 * hbarp + 6.0)) - 0.20 * std::cos(radians(4.0 * hbarp - 63.0));
  const double dTheta = 30.0 * std::exp(-std::pow((hbarp - 275.0) / 25.0, 2.0));
  const double Cbarp7 = std::pow(Cbarp, 7.0);
  const double RC = 2.0 * std::sqrt(Cbarp7 / (Cbarp7 + std::pow(25.0, 7.0)));
  const double Lm50 = (Lbarp - 50.0) * (Lbarp - 50.0);
  const double SL = 1.0 + 0.015 * Lm50 / std::sqrt(20.0 + Lm50);
  const double SC = 1.0 + 0.045 * Cbarp, SH = 1.0 + 0.015 * Cbarp * T;
  const double RT = -std::sin(radians(2.0 * dTheta)) * RC;
  // Equation 22.
  const double l = dLp / SL, c = dCp / SC, h = dHp / SH;
  return std::sqrt(l * l + c * c + h * h + RT * c * h);
}

}  // namespace cosim
