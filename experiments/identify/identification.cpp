#include "experiments/identify/identification.h"

namespace cosim {

IdentificationResult identify(const std::vector<IdentificationLog>& logs,
                              const IdentifyOptions& options) {
  IdentificationResult r;
  for (const auto& log : logs) r.logs.push_back(log.file);
  // In dependency order: the motor map drives the lag fit; k_f gives the mass; the mass the
  // drag (its regressor is per unit mass).
  fitMotorMap(logs, options, r);
  fitThrustCoefficient(logs, r);
  fitMotorLag(logs, options, r);
  fitHoverMass(logs, options, r);
  fitRotorDrag(logs, options, r);
  fitImuNoise(logs, options, r);
  fitAttitudeTracking(logs, r);
  return r;
}

}  // namespace cosim
