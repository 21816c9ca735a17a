#pragma once
// Text from the user (a scenario's file name, a vehicle's name) placed into a file format that
// must stay well formed whatever the bytes: SVG and JSON need valid UTF-8 without control
// characters. File names on Linux are any bytes but '/' and NUL.
#include <string>

namespace cosim {

// `text` with control characters (0-31, 127) and every byte that is not part of a valid UTF-8
// sequence shown as the four characters \xNN; valid UTF-8 (a name in any script) is kept.
std::string displayText(const std::string& text);

}  // namespace cosim
