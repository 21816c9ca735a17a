#pragma once
// Whether a field of a numeric file is a number written in decimal. std::strtod also reads
// hexadecimal ("0x10" is 16), "inf", "nan" and "infinity": a file that holds them is not a
// table of measurements written by a person or a logger, so such text is refused, not read.
#include <string>

namespace cosim {

// True for [+-]digits[.digits][(e|E)[+-]digits] with at least one digit before the exponent
// ("1", "-0.5", ".5", "5.", "1e-3"); false for anything else, leading or trailing spaces too.
bool isDecimalNumberText(const std::string& text);

// `v` written with ten significant digits (as std::ostream writes it at precision 10: "0.1",
// "1e-05", "12345.6789"): the text cosim writes numbers into the MJCF it composes with, enough
// to carry a float's seven digits and the scenario's decimal values unchanged.
std::string tenSignificantDigits(double v);

}  // namespace cosim
