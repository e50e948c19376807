// MGF material values from the command line: what MGF's reference parser refuses (rd, rs, td
// outside [0, 1], cxy outside the chromaticity diagram, cct below 1000 K, ir's index up to 1e-6) is
// refused with exit 2 naming the file, line, entity and fix; rd above 0.99 and cxy's y 0 are repaired with a
// warning; a near-neutral white at rd 0.99 opens even under --strict.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "tests/cli/cli_run.h"

namespace radmesh {
namespace {

// A closed 2 m box lit by a ceiling panel; its walls are `material` (the lines after `m white =`).
std::string box(const std::string& name, const std::string& material) {
  const std::string path = tempPath(name);
  std::ofstream(path) << "m white =\n" << material
                      << "v p0 =\n p 0 0 0\nv p1 =\n p 2 0 0\nv p2 =\n p 2 2 0\nv p3 =\n p 0 2 0\n"
                         "v p4 =\n p 0 0 2\nv p5 =\n p 2 0 2\nv p6 =\n p 2 2 2\nv p7 =\n p 0 2 2\n"
                         "f p0 p1 p2 p3\nf p4 p7 p6 p5\nf p0 p4 p5 p1\nf p1 p5 p6 p2\nf p2 p6 p7 p3\nf p3 p7 p4 p0\n"
                         "m light =\n c\n ed 100\nv l0 =\n p 0.8 0.8 1.99\nv l1 =\n p 1.2 0.8 1.99\n"
                         "v l2 =\n p 1.2 1.2 1.99\nv l3 =\n p 0.8 1.2 1.99\nf l0 l3 l2 l1\n";
  return path;
}

// `radmesh info` of box(name, material) exits 2 with `radmesh: error: PATH` and `says`.
void expectInfoRefused(const std::string& name, const std::string& material, const std::string& says) {
  const std::string path = box(name, material);
  const CommandRun run = radmesh("info " + path);
  EXPECT_EQ(run.exitCode, 2) << run.output;
  EXPECT_EQ(run.output, "radmesh: error: " + path + says + "\n");
}

// `radmesh info` of `path` opens it with `warning` (after the path), and refuses it under --strict
// for its `kinds` warnings (each a kind of repair); returns what the first run printed.
std::string expectInfoRepaired(const std::string& path, const std::string& warning, int kinds) {
  const CommandRun run = radmesh("info " + path);
  EXPECT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("radmesh: warning: " + path + warning + "\n"), std::string::npos) << run.output;
  const CommandRun strict = radmesh("info --strict " + path);
  EXPECT_EQ(strict.exitCode, 2) << strict.output;
  const std::string refusal = kinds == 1 ? "refused under --strict (each warning an error): "
                                         : "refused under --strict (each warning an error), for its " +
                                               std::to_string(kinds) + " warnings:\n  ";
  EXPECT_NE(strict.output.find(path + ": " + refusal), std::string::npos) << strict.output;
  return run.output;
}

TEST(MgfValuesCli, FractionsOfLightAboveOneAreRefused) {
  const struct {
    std::string name, material, says;
  } cases[] = {
      {"rd5.mgf", " c\n rd 5\n",
       ": line 3: rd: diffuse reflectance 5 is above 1 (more light than falls on the surface) (fix: write rd as a "
       "fraction of the light, from 0 up to 1 (50% is 0.5))"},
      {"rs5.mgf", " c\n rd 0.5\n rs 5 0.1\n",
       ": line 4: rs: specular reflectance 5 is above 1 (more light than falls on the surface) (fix: write rs as a "
       "fraction of the light, from 0 up to 1 (50% is 0.5))"},
      {"td5.mgf", " c\n rd 0.5\n td 5\n",
       ": line 4: td: diffuse transmittance 5 is above 1 (more light than falls on the surface) (fix: write td as a "
       "fraction of the light, from 0 up to 1 (50% is 0.5))"},
      {"td-neg.mgf", " c\n rd 0.5\n td -0.2\n",
       ": line 4: td: diffuse transmittance -0.2 is negative (fix: write td as a fraction of the light, from 0 up "
       "to 1 (50% is 0.5))"},
  };
  for (const auto& c : cases) expectInfoRefused(c.name, c.material, c.says);
}

// MGF's reference parser refuses a chromaticity outside the diagram, which radmesh had clipped
// into it with a warning; y = 0, which it opens, is raised with a warning.
TEST(MgfValuesCli, ChromaticityOutsideTheDiagramIsRefused) {
  const std::string needs = " is impossible (needs x >= 0, y > 0, x + y <= 1) (fix: give CIE 1931 x y of a real "
                            "colour, e.g. cxy 0.333 0.333 for white)";
  for (const auto& [xy, shown] : {std::pair{"0.7 0.5", "(0.7, 0.5)"}, std::pair{"-0.1 0.3", "(-0.1, 0.3)"},
                                  std::pair{"0.3 -0.1", "(0.3, -0.1)"}, std::pair{"1.5 0", "(1.5, 0)"}})
    expectInfoRefused("cxy.mgf", std::string(" c\n  cxy ") + xy + "\n rd 0.5\n",
                      std::string(": line 3: cxy: chromaticity ") + shown + needs);
  // Its second repair: the colour lies outside the Rec. 709 gamut.
  expectInfoRepaired(box("cxy-y0.mgf", " c\n  cxy 0.5 0\n rd 0.5\n"),
                     ": line 3: cxy y 0 (light of no luminance, which rd and ed cannot scale) raised to 1e-06", 2);
}

// Below what MGF's reference parser reads, a colour temperature or an index of refraction had
// opened: refused, exit 2.
TEST(MgfValuesCli, ColourTemperatureAndIndexOfRefractionBelowTheReferenceRangeAreRefused) {
  expectInfoRefused("cct.mgf", " c\n  cct 500\n rd 0.5\n",
                    ": line 3: cct: colour temperature 500 K is below 1000 K (fix: give cct a temperature in kelvin "
                    "from 1000 up, e.g. cct 3000)");
  expectInfoRefused("ir.mgf", " c\n rd 0.5\n ir -1 0\n",
                    ": line 4: ir: real index of refraction -1 is not above 1e-6 (fix: give ir the refractive "
                    "index, then the absorption, e.g. ir 1.5 0 for glass)");
}

// ed 1e-45 solved without a word into a bake whose float radiosities were all 0: a black picture.
// Light under the floats' reach is refused, naming the file, the material and the fix.
TEST(MgfValuesCli, LightTooFaintForTheBakeIsRefused) {
  const std::string path = box("faint.mgf", " c\n rd 0.5\n ed 1e-45\n");
  for (const std::string command : {"info ", "solve "}) {
    const CommandRun run = radmesh(command + path);
    EXPECT_EQ(run.exitCode, 2) << run.output;
    EXPECT_EQ(run.output, "radmesh: error: " + path +
                              ": material 'white': emits 5.58659e-48 W/m^2, less than the 1e-30 W/m^2 radmesh trusts "
                              "(no real light comes near; a solve's radiosities would fall below what the bake's "
                              "floats hold: a black picture) (fix: raise its emittance to a real light's, or make it 0 "
                              "if it is no light: MGF's ed is in lm/m^2, glTF's emission in W/m^2, a glTF light's "
                              "intensity in candela (lux for a directional light))\n");
  }
}

TEST(MgfValuesCli, ReflectanceOfOneIsLoweredWithAWarning) {
  const std::string output = expectInfoRepaired(
      box("rd1.mgf", " c\n  cxy 0.333 0.333\n rd 1.0\n"),
      ": line 4: rd 1 lowered to 0.99 (a reflectance of 1 never lets light die out)", 1);
  EXPECT_EQ(output.find("gamut"), std::string::npos) << output;
}

// Between 0.99 and 1 it was lowered without a word, and --strict let it through (glTF's warns).
TEST(MgfValuesCli, AReflectanceAbove099IsLoweredWithAWarning) {
  expectInfoRepaired(box("rd995.mgf", " rd 0.995\n"),
                     ": line 2: rd 0.995 lowered to 0.99 (the highest reflectance radmesh solves: the nearer 1, "
                     "the longer light takes to die out)",
                     1);
}

// A floor listed twice split the light between the copies, one lit and one black, and the bake,
// whose copies share vertices, showed it at about 60 % of its brightness. The copy is dropped, with
// a warning (--strict refuses it), and the solve is the single floor's.
TEST(MgfValuesCli, AFaceListedTwiceIsDroppedWithAWarning) {
  const std::string single = box("single.mgf", " c\n rd 0.5\n");
  const std::string doubled = tempPath("doubled.mgf");
  {
    std::ifstream in(single);
    std::ofstream(doubled) << in.rdbuf() << "m white\nf p0 p1 p2 p3\n";
  }
  expectInfoRepaired(doubled,
                     ": 1 polygon(s) repeat an earlier one exactly (corners, side and material), the first polygon 7 "
                     "(line 39: f): dropped, as copies would split the light falling there (one lit, one black)",
                     1);
  std::string ledgers[2];
  for (int k = 0; k < 2; ++k) {
    const CommandRun run = radmesh("solve " + (k ? doubled : single) + " --resolution 32 --threads 1 --quiet");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    ledgers[k] = run.output.substr(run.output.find("ledger:"));
    ledgers[k] = ledgers[k].substr(0, ledgers[k].find('\n'));
  }
  EXPECT_EQ(ledgers[1], ledgers[0]);
}

// MGF's white to three digits and D65 at rd 0.99 had warned "outside the Rec. 709 gamut", and
// --strict refused the reference scenes' own white.
TEST(MgfValuesCli, NearNeutralWhiteAtTheHighestReflectanceOpensUnderStrict) {
  for (const std::string white : {"0.333 0.333", "0.3127 0.3290"}) {
    const std::string path = box("white.mgf", " c\n  cxy " + white + "\n rd 0.99\n");
    const CommandRun run = radmesh("info --strict " + path);
    EXPECT_EQ(run.exitCode, 0) << white << ": " << run.output;
    EXPECT_EQ(run.output.find("warning"), std::string::npos) << white << ": " << run.output;
  }
  const std::string path = box("red.mgf", " c\n  cxy 0.75 0.10\n rd 0.99\n");
  const CommandRun run = radmesh("info --strict " + path);
  EXPECT_EQ(run.exitCode, 2) << run.output;
  EXPECT_NE(run.output.find(path + ": refused under --strict (each warning an error): line 21: material 'white': its "
                            "colour lies outside the Rec. 709 gamut; desaturated toward grey, keeping its luminance "
                            "(fix: correct what the warning names, or leave --strict out to open it as warned)"),
            std::string::npos)
      << run.output;
}

}  // namespace
}  // namespace radmesh
