// --sun AZIMUTH,ELEVATION[,LUX]: the sun's direction and irradiance, and what is refused.
#include <gtest/gtest.h>

#include <utility>

#include <cmath>

#include "solver/scene/scene_error.h"
#include "solver/scene/sun.h"

namespace radmesh {
namespace {

TEST(Sun, AzimuthIsClockwiseFromNorthAndElevationAboveTheHorizon) {
  const Light east = parseSun("90,30");  // in the east, 30 degrees up: its light travels west and down
  EXPECT_EQ(east.type, LightType::Directional);
  EXPECT_NEAR(east.direction.x, -std::cos(M_PI / 6), 1e-15);
  EXPECT_NEAR(east.direction.y, 0.0, 1e-15);
  EXPECT_NEAR(east.direction.z, -0.5, 1e-15);
  EXPECT_DOUBLE_EQ(east.intensity.r, kClearSkySunLux / kWhiteEfficacyLmPerW);  // 100000 lux by default
  const Light north = parseSun("0,45,50000");
  EXPECT_NEAR(north.direction.y, -std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(north.direction.x, 0.0, 1e-15);
  EXPECT_DOUBLE_EQ(north.intensity.g, 50000 / 179.0);
}

TEST(Sun, ImpossibleValuesAreRefusedNamingTheOption) {
  for (const char* bad : {"10,0", "10,-5", "10,91", "a,45", "10", "10,45,0", "10,45,1e-40", "10,45,nan", "10,45,inf", "10,45,133001", "10,45,1e308", "", "10,45,1,2", "10,,45"}) {
    try {
      parseSun(bad);
      ADD_FAILURE() << "--sun " << bad << " accepted";
    } catch (const OptionError& e) {
      EXPECT_NE(std::string(e.what()).find("--sun"), std::string::npos) << e.what();
    }
  }
  EXPECT_DOUBLE_EQ(parseSun("10,45,133000").intensity.g, 133000 / 179.0);  // the sun above the atmosphere
  // Past overhead is said as such (it read "not above the horizon").
  for (const auto& [sun, says] : {std::pair{"10,91", "--sun elevation 91 is past overhead"},
                                  std::pair{"10,-5", "--sun elevation -5 is not above the horizon"}})
    try {
      parseSun(sun);
      ADD_FAILURE() << sun;
    } catch (const OptionError& e) {
      EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace radmesh
