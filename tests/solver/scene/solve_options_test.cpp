#include "solver/scene/solve_options.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "solver/scene/scene_error.h"

namespace radmesh {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;

std::string refusal(SolveOptions o) {
  try {
    validateOptions(o);
  } catch (const OptionError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(SolveOptions, DefaultsAndRangeEndsAreAccepted) {
  EXPECT_NO_THROW(validateOptions(SolveOptions{}));
  SolveOptions o;
  o.resolution = 16;
  o.until = 1.0;
  o.threads = 0;
  EXPECT_NO_THROW(validateOptions(o));
  o.resolution = 2048;
  EXPECT_NO_THROW(validateOptions(o));
}

TEST(SolveOptions, RefusalsNameTheFlagAndTheRange) {
  SolveOptions o;
  o.resolution = 15;
  EXPECT_THAT(refusal(o), AllOf(HasSubstr("--resolution 15"), HasSubstr("16 to 2048")));
  o = {};
  o.resolution = 2049;
  EXPECT_THAT(refusal(o), HasSubstr("--resolution 2049"));
  o = {};
  o.ratio = std::nan("");
  EXPECT_THAT(refusal(o), AllOf(HasSubstr("--ratio nan"), HasSubstr("positive")));
  o = {};
  o.ratio = 0.0;
  EXPECT_THAT(refusal(o), HasSubstr("--ratio 0 "));
  o = {};
  o.shooters = 0;
  EXPECT_THAT(refusal(o), AllOf(HasSubstr("--shooters 0"), HasSubstr("at least 1")));
  o = {};
  o.until = 0.0;
  EXPECT_THAT(refusal(o), AllOf(HasSubstr("--until 0"), HasSubstr("(0, 1]")));
  o = {};
  o.until = 1.5;
  EXPECT_THAT(refusal(o), HasSubstr("--until 1.5"));
  o = {};
  o.untilUnshot = 1.0;
  EXPECT_THAT(refusal(o), AllOf(HasSubstr("--until-unshot 1"), HasSubstr("[0, 1)")));
  o = {};
  o.untilUnshot = -0.01;
  EXPECT_THAT(refusal(o), HasSubstr("--until-unshot -0.01"));
  o = {};
  o.maxIterations = 0;
  EXPECT_THAT(refusal(o), HasSubstr("--max-iterations 0"));
  o = {};
  o.threads = -1;
  EXPECT_THAT(refusal(o), HasSubstr("--threads -1"));
}

TEST(SolveOptions, PeGridParsesPowersOfTwoAndRefusesOthersByName) {
  PeMachine m;
  parsePeGrid("256x128", m);
  EXPECT_EQ(m.cols, 256);
  EXPECT_EQ(m.rows, 128);
  EXPECT_EQ(peGridText(m), "256x128");
  for (const char* bad : {"64", "x64", "64x", "64x64x2", "ax64", "64 x 64"}) {
    PeMachine unchanged;
    try {
      parsePeGrid(bad, unchanged);
      ADD_FAILURE() << bad << " was accepted";
    } catch (const OptionError& e) {
      EXPECT_THAT(e.what(), AllOf(HasSubstr(std::string("--pe-grid '") + bad + "'"), HasSubstr("e.g. 128x128")));
    }
    EXPECT_EQ(peGridText(unchanged), "64x64") << bad;
  }
  SolveOptions o;
  for (const char* good : {"2x2", "128x128", "256x256", "1024x64"}) {
    parsePeGrid(good, o.machine);
    EXPECT_NO_THROW(validateOptions(o)) << good;
  }
  for (const char* notPowerOfTwo : {"48x64", "64x0", "1x64", "2048x64", "-64x64"}) {
    parsePeGrid(notPowerOfTwo, o.machine);
    EXPECT_THAT(refusal(o), AllOf(HasSubstr(std::string("--pe-grid ") + notPowerOfTwo), HasSubstr("powers of two from 2 to 1024")));
  }
  o = {};
  o.machine.memoryKb = 0;
  EXPECT_THAT(refusal(o), AllOf(HasSubstr("--pe-memory 0"), HasSubstr("KB from 1 to 1048576")));
  o.machine.memoryKb = 1024 * 1024;
  EXPECT_NO_THROW(validateOptions(o));
}

TEST(SolveOptions, NamesRoundTripAndUnknownNamesAreRefused) {
  for (Projection p : {Projection::Plane, Projection::Hemicube, Projection::Analytic})
    EXPECT_EQ(parseProjection(toString(p)), p);
  for (Backend b : {Backend::Native, Backend::Mesh}) EXPECT_EQ(parseBackend(toString(b)), b);
  for (Preset p : {Preset::Bake, Preset::Paper, Preset::Elements}) EXPECT_EQ(parsePreset(toString(p)), p);
  EXPECT_THROW(parseProjection("sphere"), OptionError);
  EXPECT_THROW(parseBackend("gpu"), OptionError);
  EXPECT_THROW(parsePreset("fast"), OptionError);
}

// Round measures stay round: a cell a hair off the model's grid would cut slivers along its edges.
TEST(SolveOptions, ThePresetElementsCellIsTheScenesTimes2625ToTwoFigures) {
  EXPECT_EQ(elementsPresetCell(0.381), 1.0);  // 1.000125
  EXPECT_DOUBLE_EQ(elementsPresetCell(0.0343), 0.09);
  EXPECT_DOUBLE_EQ(elementsPresetCell(0.75), 2.0);   // 1.96875
  EXPECT_DOUBLE_EQ(elementsPresetCell(4.0), 11.0);   // 10.5, halfway, rounds up
}

}  // namespace
}  // namespace radmesh
