#pragma once
// The random stream of one sensor: xoshiro256++ (core/xoshiro256pp.h) seeded through
// std::seed_seq from the caller's seed and a constant of the sensor kind, so that the same seed
// gives the same noise every run (determinism: same scenario and seed, same result) while an IMU, a
// position sensor and an attitude sensor given one seed still draw independent noise.
#include <cstdint>
#include <random>

#include "core/xoshiro256pp.h"

namespace cosim {

enum class SensorKind : std::uint32_t { kImu = 1, kPosition = 2, kAttitude = 3 };

using SensorNoiseEngine = Xoshiro256pp;

inline SensorNoiseEngine sensorNoiseStream(std::uint64_t seed, SensorKind kind) {
  std::seed_seq seq{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32),
                    static_cast<std::uint32_t>(kind)};
  return SensorNoiseEngine(seq);
}

}  // namespace cosim
