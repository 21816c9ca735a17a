#pragma once
// When the EKF fuses a fix that reaches it late (estimation/latency_compensated_ekf.h).
namespace cosim {

enum class FixTiming {
  AtValidity,  // at the instant the fix was valid for, exactly, by re-running the steps since
  OnArrival,   // at the latest prediction when it arrives, as the Crazyflie's estimator does
};

}  // namespace cosim
