#pragma once
// How a flight log's samples are stored as the flight goes: a modest reservation up front that
// then doubles whenever it is full. Reserving for the whole of sim.max_time cost a long
// max_time (39990 s of a 7 s flight at 500 Hz) 7.3 GB and 36 s before the first step; growing
// costs a flight what it logs (at most twice that while it grows, amortised copies, and never
// more than the whole run's reservation). Each growth
// writes the new samples once, as the reservation did, so that the loop does not meet the first
// touch of each page of its log (a page fault, in a virtual machine often a trip to the host)
// sample by sample.
#include <cstddef>
#include <vector>

#include "sim/run_log.h"

namespace cosim {

// The log memory reserved up front for all vehicles together: 16 MB (a sample is 368 bytes:
// 45590 samples, 91 s at 500 Hz, for one vehicle; 91 samples each for 500).
constexpr std::size_t kInitialLogBytes = std::size_t{16} << 20;
// The fewest samples reserved for a vehicle.
constexpr std::size_t kMinInitialLogSamples = 64;

// The samples to reserve for each of `vehicles` vehicles that would log `expected` samples if
// they flew for the whole run.
std::size_t initialLogSamples(std::size_t expected, std::size_t vehicles);

// Reserves `n` samples in `samples` (empty), each written once.
void reserveLogSamples(std::vector<LogSample>& samples, std::size_t n);

// Doubles the storage of a full log, but to no more than `most` samples (what the whole run can
// log: the log never holds more room than reserving for sim.max_time did), the new samples
// written once.
void growLogSamples(std::vector<LogSample>& samples, std::size_t most);

// The next sample of a log that holds at most `most`, default-constructed; its storage doubles
// when full.
inline LogSample& appendLogSample(std::vector<LogSample>& samples, std::size_t most) {
  if (samples.size() == samples.capacity()) growLogSamples(samples, most);
  return samples.emplace_back();
}

}  // namespace cosim
