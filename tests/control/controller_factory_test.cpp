// The flight controller factory, now in control/ beside the controllers it builds: a misspelt
// name or gain is bad input naming the scenario file and the key, not a controller that silently
// ignores it.
#include "control/controller_factory.h"

#include <gtest/gtest.h>

#include "closed_loop_flight.h"
#include "core/input_error.h"
#include "tests/support/input_error_message.h"

namespace cosim {
namespace {

using testing::quad1500g;

std::string messageOf(const std::function<void()>& build) {
  return test::inputErrorMessageOf(build);
}

TEST(ControllerFactory, UnknownNameNamesTheFileAndKey) {
  ParamSet gains("trip.yaml");
  const std::string m = messageOf([&] { makeFlightController("geometirc", gains, quad1500g()); });
  EXPECT_NE(m.find("trip.yaml"), std::string::npos) << m;
  EXPECT_NE(m.find("controller.name"), std::string::npos) << m;
  EXPECT_NE(m.find("geometirc"), std::string::npos) << m;
}

TEST(ControllerFactory, DragCompensationOnlyForGeometricAndIndi) {
  for (const std::string name : {"cascade", "dsl_pid"}) {
    ParamSet gains("trip.yaml");
    EXPECT_NE(messageOf([&] {
                makeFlightController(name, gains, quad1500g(), true);
              }).find("controller.drag_compensation"),
              std::string::npos)
        << name;
  }
  for (const std::string name : {"geometric", "indi"}) {
    ParamSet gains("trip.yaml");
    EXPECT_EQ(messageOf([&] { makeFlightController(name, gains, quad1500g(), true); }),
              "no InputError")
        << name;
  }
}

TEST(ControllerFactory, AMisspeltGainIsAnError) {
  ParamSet gains("trip.yaml");
  gains.set("kp_xyy", "3");
  const std::string m = messageOf([&] { makeFlightController("cascade", gains, quad1500g()); });
  EXPECT_NE(m.find("kp_xyy"), std::string::npos) << m;
}

}  // namespace
}  // namespace cosim
