#pragma once
// How different two colours look: sRGB to CIELAB and the CIEDE2000 colour difference, used to
// choose and check the vehicle palette (render/vehicle_palette.h).
#include <Eigen/Core>

namespace cosim {

// CIELAB (L*, a*, b*) of an sRGB colour (each channel 0..1), white point D65: the sRGB transfer
// function and matrix of IEC 61966-2-1 (1999), then CIE 15:2004's L*a*b* with Xn, Yn, Zn =
// 0.95047, 1.0, 1.08883 (D65, 2-degree observer).
Eigen::Vector3d srgbToLab(const Eigen::Vector3f& rgb);

// The CIEDE2000 colour difference of two CIELAB colours (kL = kC = kH = 1), as Sharma, Wu &
// Dalal set it out ("The CIEDE2000 Color-Difference Formula: Implementation Notes,
// Supplementary Test Data, and Mathematical Observations", Color Res. Appl. 30(1), 2005,
// equations 1-22). About 1 is a just-noticeable difference; 10 reads as another colour.
double ciede2000(const Eigen::Vector3d& lab1, const Eigen::Vector3d& lab2);

}  // namespace cosim
