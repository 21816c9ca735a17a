#pragma once
// The value on one of index.html's headline cards, rounded to what a reader can use: metres
// below one as centimetres with three significant digits (0.04465849305871672 -> "4.47 cm"),
// seconds with two decimals (29.23000000001274 -> "29.23 s"). The metrics table keeps the full
// numbers of metrics.json.
#include <string>

namespace cosim {

// key: a metrics.json key (its suffix names the unit: _m, _s, _ms, _mps); value: the value as
// metrics.json writes it. Values that are not numbers (true, "theta_star") come back unchanged.
std::string cardValue(const std::string& key, const std::string& value);

}  // namespace cosim
