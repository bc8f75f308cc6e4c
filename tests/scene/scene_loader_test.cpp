// Every validation rule of shared/scene-format.md: each bad input is fed through ParseScene and
// the error must name the file, the key and what was expected. Good scenes load, with defaults.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include "core/line_equilibrium.h"
#include "core/error.h"
#include "core/waves.h"
#include "scene/build_model.h"
#include "scene/film_settings.h"
#include "scene/moordyn_convert.h"
#include "scene/moordyn_file.h"
#include "scene/scene_limits.h"
#include "scene/scene_loader.h"
#include "core/inputs.h"
#include "line_of.h"

namespace cablefilm {
namespace {

const char* kFile = "scenes/bad_scene.toml";

// A complete valid scene; tests replace one piece of it.
const std::string kBase = R"(title = "base"

[environment]
gravity = 9.80665
fluid_density = 1025.0
current = 0.0

[[material]]
name = "wire"
diameter = 0.0254
area = 5.067e-4
mass_per_length = 2.75
youngs_modulus = 9.0e10

[[material]]
name = "nylon"
diameter = 0.0508
area = 2.027e-3
mass_per_length = 1.70
youngs_modulus = 2.0e9

[cable]
model = "elastic"

[[cable.section]]
material = "wire"
length = 45.72
segments = 30

[[cable.section]]
material = "nylon"
length = 45.72
segments = 30

[[cable.weight]]
at = 27.432
mass = 453.6
volume = 0.0578

[ends.start]
position = [0.0, 0.0]
motion = "fixed"

[ends.end]
position = [80.0, 30.48]
motion = "trochoid"
x_amplitudes = [1.8288, 0.0]
y_amplitudes = [0.0, 1.8288]
period = 10.0
ramp_rate = 0.5

[simulation]
duration = 60.0
time_step = "auto"

[output]
film = false
)";

// kBase with the first occurrence of `from` replaced by `to` (which must be present).
std::string With(const std::string& from, const std::string& to, std::string text = kBase) {
  const size_t at = text.find(from);
  if (at == std::string::npos) throw std::logic_error("test bug: no \"" + from + "\" in base");
  return text.replace(at, from.size(), to);
}

// Parses `text` expecting an Error whose message contains the file, `key` and every piece of
// `expected`.
void ExpectError(const std::string& text, const std::string& key,
                 const std::vector<std::string>& expected, const std::string& file = kFile) {
  try {
    ParseScene(text, file);
    ADD_FAILURE() << "no error for key " << key;
  } catch (const Error& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(file + ":"), std::string::npos) << "file not named: " << msg;
    EXPECT_NE(msg.find(key), std::string::npos) << "key " << key << " not named: " << msg;
    for (const std::string& s : expected)
      EXPECT_NE(msg.find(s), std::string::npos) << "\"" << s << "\" not in: " << msg;
  }
}

TEST(SceneLoader, BaseSceneLoads) {
  const SceneDef s = ParseScene(kBase, kFile);
  EXPECT_EQ(s.lines[0].sections.size(), 2u);
  EXPECT_EQ(s.lines[0].weights.size(), 1u);
  EXPECT_EQ(s.name, "bad_scene");
  EXPECT_EQ(LineOf(s).line.weight_stations, std::vector<int>{18});
}

TEST(SceneLoader, UnknownKeys) {
  ExpectError(kBase + "colour = 3\n", "colour", {"unknown key"});
  ExpectError(With("gravity = 9.80665", "gravity = 9.80665\ngravty = 9.8"), "environment.gravty",
              {"unknown key"});
  ExpectError(With("segments = 30\n\n[[cable.weight]]", "segments = 30\nlenght = 3\n\n[[cable.weight]]"),
              "cable.section[1].lenght", {"unknown key"});
  ExpectError(With("volume = 0.0578", "volume = 0.0578\nvolum = 1"), "cable.weight[0].volum",
              {"unknown key"});
  ExpectError(With("name = \"nylon\"", "name = \"nylon\"\ncolor = \"red\""), "material[1].color",
              {"unknown key"});
  // A key that belongs to another motion kind is unknown for this one.
  ExpectError(With("motion = \"fixed\"", "motion = \"fixed\"\nperiod = 3.0"), "ends.start.period",
              {"unknown key"});
  ExpectError(kBase + "[film]\nwidht = 640\n", "film.widht", {"unknown key"});
}

TEST(SceneLoader, WeightNotOnAStation) {
  // 27.0 m is between stations (1.524 m apart); 100 m is past the end (91.44 m).
  ExpectError(With("at = 27.432", "at = 27.0"), "cable.weight[0].at",
              {"expected the arc length of a station", "27"});
  ExpectError(With("at = 27.432", "at = 100.0"), "cable.weight[0].at", {"expected", "91.44"});
  ExpectError(With("at = 27.432", "at = -1.524"), "cable.weight[0].at", {"expected"});
  // On a station of the second section (45.72 + 10 * 1.524 m): fine.
  EXPECT_NO_THROW(ParseScene(With("at = 27.432", "at = 60.96"), kFile));
}

// A cable too long for the statics' bound (kMostLineStaticsWork station-passes, and a line's
// statics take kLeastStaticPasses over its stations at the least) is refused at its longest
// section's segments when it starts from its equilibrium, before its model is made (10^7 links
// made 3.5 GB of it, and the statics gave up seconds later); from the chord it runs.
TEST(SceneLoader, ACableTooLongForTheStaticsIsRefusedAtItsSegments) {
  const double most = std::floor(kMostLineStaticsWork / kLeastStaticPasses) - 1;  // links
  // Sections of a multiple of 5 links: the weight 0.6 of the way along the first on a station.
  const int half = 5 * (static_cast<int>(most / 10) + 1);  // 3 x half > most
  const std::string longer = With(
      "segments = 30\n\n[[cable.section]]\nmaterial = \"nylon\"\nlength = 45.72\nsegments = 30",
      "segments = " + std::to_string(2 * half) + "\n\n[[cable.section]]\nmaterial = \"nylon\"\n"
      "length = 45.72\nsegments = " + std::to_string(half));
  ExpectError(longer, "cable.section[0].segments",
              {"station-passes", "[initial] state = \"straight\"",
               "expected at most " + std::to_string(static_cast<long long>(most)) + " links"});
  EXPECT_NO_THROW(ParseScene(longer + "\n[initial]\nstate = \"straight\"\n", kFile));
  // Just within it, it is taken.
  const int first = 5 * (static_cast<int>(most / 5) - 6);  // with the other's 30
  EXPECT_NO_THROW(ParseScene(With("segments = 30", "segments = " + std::to_string(first)), kFile));
}

TEST(SceneLoader, SectionWithoutSegments) {
  ExpectError(With("segments = 30", "segments = 0"), "cable.section[0].segments",
              {"expected a whole number from 1"});
  ExpectError(With("segments = 30", "segments = 2.5"), "cable.section[0].segments",
              {"expected a whole number"});
  ExpectError(With("length = 45.72\nsegments = 30", "length = 45.72"), "cable.section[0].segments",
              {"missing"});
  ExpectError(With("[[cable.section]]\nmaterial = \"wire\"\nlength = 45.72\nsegments = 30\n\n"
                   "[[cable.section]]\nmaterial = \"nylon\"\nlength = 45.72\nsegments = 30\n",
                   "section = []\n"),
              "cable.section", {"expected"});
}

TEST(SceneLoader, StartToleranceKeys) {
  const auto with = [](const std::string& lines) {
    return With("time_step = \"auto\"", "time_step = \"auto\"\n" + lines);
  };
  SimulationDef s = ParseScene(with("start_duration = \"auto\"\nstart_tolerance = 1e-6"), kFile).simulation;
  EXPECT_LT(s.start_duration, 0);  // auto
  EXPECT_EQ(s.start_tolerance, 1e-6);
  EXPECT_EQ(ParseScene(with("start_duration = 4.5"), kFile).simulation.start_duration, 4.5);
  EXPECT_EQ(ParseScene(with("start_duration = 0"), kFile).simulation.start_duration, 0.0);
  EXPECT_LT(ParseScene(kBase, kFile).simulation.start_duration, 0);
  ExpectError(with("start_duration = \"soon\""), "simulation.start_duration",
              {"expected \"auto\" or a number of seconds from 0 to 1e9"});
  ExpectError(with("start_duration = -1.0"), "simulation.start_duration", {"expected \"auto\""});
  ExpectError(with("start_duration = 2e9"), "simulation.start_duration", {"expected \"auto\""});
  ExpectError(with("start_duration = true"), "simulation.start_duration", {"expected \"auto\""});
  ExpectError(with("start_tolerance = 0.0"), "simulation.start_tolerance", {"expected a positive number"});
  ExpectError(with("start_tolerance = \"auto\""), "simulation.start_tolerance", {"expected"});
}

TEST(SceneLoader, NonPositiveQuantities) {
  ExpectError(With("segments = 30\n\n[[cable.weight]]", "segments = 30\n\n[[cable.weight]]",
                   With("length = 45.72\nsegments = 30\n\n[[cable.weight]]",
                        "length = -1.0\nsegments = 30\n\n[[cable.weight]]")),
              "cable.section[1].length", {"expected a positive number", "-1"});
  ExpectError(With("length = 45.72", "length = 0"), "cable.section[0].length",
              {"expected a positive number", "got 0"});
  ExpectError(With("mass_per_length = 2.75", "mass_per_length = 0.0"), "material[0].mass_per_length",
              {"expected a positive number"});
  ExpectError(With("area = 2.027e-3", "area = -2.027e-3"), "material[1].area",
              {"expected a positive number"});
  ExpectError(With("youngs_modulus = 2.0e9", "youngs_modulus = 0"), "material[1].youngs_modulus",
              {"expected a positive number"});
  ExpectError(With("diameter = 0.0254", "diameter = 0"), "material[0].diameter",
              {"expected a positive number"});
  ExpectError(With("mass = 453.6", "mass = -453.6"), "cable.weight[0].mass",
              {"expected a positive number"});
  ExpectError(With("volume = 0.0578", "volume = -1"), "cable.weight[0].volume", {"expected"});
  ExpectError(With("period = 10.0", "period = 0.0"), "ends.end.period",
              {"expected a positive number"});
  ExpectError(With("ramp_rate = 0.5", "ramp_rate = -0.5"), "ends.end.ramp_rate",
              {"expected a positive number"});
  ExpectError(With("duration = 60.0", "duration = 0.0"), "simulation.duration",
              {"expected a positive number"});
  ExpectError(With("fluid_density = 1025.0", "fluid_density = -1.0"),
              "environment.fluid_density", {"expected a number >= 0"});
}

TEST(SceneLoader, AxialDamping) {
  ExpectError(With("youngs_modulus = 2.0e9", "youngs_modulus = 2.0e9\naxial_damping = -1"),
              "material[1].axial_damping", {"expected a number >= 0"});
  ExpectError(With("youngs_modulus = 2.0e9", "youngs_modulus = 2.0e9\naxial_damping_ratio = 1e9"),
              "material[1].axial_damping_ratio", {"100"});
  ExpectError(With("youngs_modulus = 2.0e9",
                   "youngs_modulus = 2.0e9\naxial_damping = 1e5\naxial_damping_ratio = 0.5"),
              "material[1].axial_damping_ratio", {"not both"});
}

// The tangential (axial) drag and added mass: 0 by default, read as given, refused negative or
// above the coefficients' limit with the file, the key and what was expected.
TEST(SceneLoader, TangentialDragAndAddedMass) {
  const SceneDef plain = ParseScene(kBase, kFile);
  for (const MaterialDef& m : plain.materials) {
    EXPECT_EQ(m.tangential_drag_coefficient, 0.0);
    EXPECT_EQ(m.tangential_added_mass_coefficient, 0.0);
  }
  const SceneDef s = ParseScene(
      With("youngs_modulus = 2.0e9",
           "youngs_modulus = 2.0e9\ntangential_drag_coefficient = 0.4\n"
           "tangential_added_mass_coefficient = 0.5"),
      kFile);
  EXPECT_EQ(s.materials[1].tangential_drag_coefficient, 0.4);
  EXPECT_EQ(s.materials[1].tangential_added_mass_coefficient, 0.5);
  ExpectError(With("youngs_modulus = 2.0e9", "youngs_modulus = 2.0e9\ntangential_drag_coefficient = -0.1"),
              "material[1].tangential_drag_coefficient", {"expected a number >= 0"});
  ExpectError(With("youngs_modulus = 2.0e9",
                   "youngs_modulus = 2.0e9\ntangential_added_mass_coefficient = -1"),
              "material[1].tangential_added_mass_coefficient", {"expected a number >= 0"});
  ExpectError(With("youngs_modulus = 2.0e9",
                   "youngs_modulus = 2.0e9\ntangential_added_mass_coefficient = 1e9"),
              "material[1].tangential_added_mass_coefficient", {"1000"});
  ExpectError(With("youngs_modulus = 2.0e9", "youngs_modulus = 2.0e9\ntangential_drag_coefficient = nan"),
              "material[1].tangential_drag_coefficient", {"non-finite"});
}

// The Froude-Krylov force along the line in waves: on unless the material leaves it out; the
// model's fluid mass along each link is then rho sigma l (1 + k^t), else e^t = rho sigma l k^t.
TEST(SceneLoader, AxialFroudeKrylov) {
  const std::string waves = "\n[waves]\nheight = 2\nperiod = 8\ndepth = 50\n";
  const SceneDef on = ParseScene(
      With("youngs_modulus = 2.0e9", "youngs_modulus = 2.0e9\ntangential_added_mass_coefficient = 0.5") +
          waves,
      kFile);
  for (const MaterialDef& m : on.materials) EXPECT_TRUE(m.axial_froude_krylov);
  const SceneDef off = ParseScene(
      With("youngs_modulus = 2.0e9", "youngs_modulus = 2.0e9\ntangential_added_mass_coefficient = "
                                     "0.5\naxial_froude_krylov = false") +
          waves,
      kFile);
  EXPECT_TRUE(off.materials[0].axial_froude_krylov);
  EXPECT_FALSE(off.materials[1].axial_froude_krylov);
  const LineModel m_on = LineOf(on), m_off = LineOf(off);
  const int last = m_on.line.links - 1;  // a link of the nylon, material[1]
  const double displaced = 1025.0 * 2.027e-3 * m_on.line.rest_length[last];  // rho sigma l [kg]
  EXPECT_DOUBLE_EQ(m_on.line.link_axial_fluid_mass[last], 1.5 * displaced);
  EXPECT_DOUBLE_EQ(m_off.line.link_axial_fluid_mass[last], 0.5 * displaced);
  EXPECT_DOUBLE_EQ(m_off.line.link_axial_fluid_mass[0], m_on.line.link_axial_fluid_mass[0]);
  ExpectError(With("youngs_modulus = 2.0e9", "youngs_modulus = 2.0e9\naxial_froude_krylov = 0"),
              "material[1].axial_froude_krylov", {"expected true or false"});
}

// Where the Airy formulas are evaluated: Wheeler's stretching unless the scene says otherwise;
// any other name is refused with the file, the key and the three expected.
TEST(SceneLoader, WaveKinematics) {
  const std::string waves = kBase + "\n[waves]\nheight = 2\nperiod = 8\ndepth = 50\n";
  EXPECT_EQ(ParseScene(waves, kFile).waves.kinematics, WaveKinematics::kWheeler);
  EXPECT_EQ(LineOf(ParseScene(waves, kFile)).env.wave.spec.kinematics, WaveKinematics::kWheeler);
  EXPECT_EQ(LineOf(ParseScene(waves + "kinematics = \"linear\"\n", kFile)).env.wave.spec.kinematics,
            WaveKinematics::kLinear);
  EXPECT_EQ(LineOf(ParseScene(waves + "kinematics = \"extrapolated\"\n", kFile))
                .env.wave.spec.kinematics,
            WaveKinematics::kExtrapolated);
  EXPECT_EQ(ParseScene(waves + "kinematics = \"wheeler\"\n", kFile).waves.kinematics,
            WaveKinematics::kWheeler);
  ExpectError(waves + "kinematics = \"stretched\"\n", "waves.kinematics",
              {"expected one of \"wheeler\", \"linear\", \"extrapolated\"", "got \"stretched\""});
  ExpectError(waves + "kinematics = 1\n", "waves.kinematics", {"expected one of"});
}

TEST(SceneLoader, NonFiniteNumbers) {
  ExpectError(With("length = 45.72", "length = nan"), "cable.section[0].length", {"non-finite"});
  ExpectError(With("youngs_modulus = 2.0e9", "youngs_modulus = inf"),
              "material[1].youngs_modulus", {"non-finite"});
  ExpectError(With("current = 0.0", "current = -inf"), "environment.current", {"non-finite"});
  ExpectError(With("position = [80.0, 30.48]", "position = [nan, 30.48]"), "ends.end.position",
              {"non-finite"});
  ExpectError(With("at = 27.432", "at = nan"), "cable.weight[0].at", {"non-finite"});
  ExpectError(With("time_step = \"auto\"", "time_step = inf"), "simulation.time_step",
              {"non-finite"});
}

TEST(SceneLoader, BadMotionAndEnds) {
  ExpectError(With("motion = \"trochoid\"", "motion = \"wobble\""), "ends.end.motion",
              {"expected one of", "\"trochoid\"", "wobble"});
  ExpectError(With("motion = \"fixed\"", "motion = 3"), "ends.start.motion", {"expected one of"});
  // Both ends free: no equilibrium.
  std::string both = With("motion = \"fixed\"", "motion = \"free\"");
  both = both.substr(0, both.find("[ends.end]")) +
         "[ends.end]\nposition = [80.0, 30.48]\nmotion = \"free\"\n";
  ExpectError(both, "ends.end.motion", {"expected at least one end that is not \"free\""});
  ExpectError(With("x_amplitudes = [1.8288, 0.0]", "x_amplitudes = [1.8288]"),
              "ends.end.x_amplitudes", {"expected an array of two numbers"});
}

TEST(SceneLoader, MissingRequiredKeys) {
  // No [[material]] at all (both renamed away: the loader then names the first missing table).
  ExpectError(With("[[material]]", "[[materia]]", With("[[material]]", "[[materia]]")), "material",
              {"missing"});
  ExpectError(With("area = 5.067e-4\n", ""), "material[0].area", {"missing", "positive"});
  ExpectError(With("position = [0.0, 0.0]\n", ""), "ends.start.position", {"missing"});
  ExpectError(With("period = 10.0\n", ""), "ends.end.period", {"missing"});
  ExpectError(With("mass = 453.6\n", ""), "cable.weight[0].mass", {"missing"});
  ExpectError(With("material = \"nylon\"\n", ""), "cable.section[1].material", {"missing"});
  ExpectError(With("material = \"nylon\"", "material = \"rope\""), "cable.section[1].material",
              {"expected the name of a [[material]]", "rope"});
  ExpectError(With("[ends.start]", "[ends.begin]"), "ends.start", {"missing"});
  ExpectError(With("name = \"nylon\"", "name = \"wire\""), "material[1].name", {"unique"});
}

TEST(SceneLoader, BadTimeStep) {
  ExpectError(With("time_step = \"auto\"", "time_step = \"fast\""), "simulation.time_step",
              {"expected \"auto\" or a positive number of seconds"});
  ExpectError(With("time_step = \"auto\"", "time_step = -0.001"), "simulation.time_step",
              {"expected \"auto\" or a positive number"});
  ExpectError(With("time_step = \"auto\"", "time_step = 0"), "simulation.time_step",
              {"expected \"auto\" or a positive number"});
  ExpectError(With("time_step = \"auto\"", "time_step = true"), "simulation.time_step",
              {"expected \"auto\" or a positive number"});
  EXPECT_DOUBLE_EQ(ParseScene(With("time_step = \"auto\"", "time_step = 0.002"), kFile)
                       .simulation.time_step,
                   0.002);
}

TEST(SceneLoader, NotToml) {
  ExpectError(With("[cable]", "[cable"), "", {"not valid TOML"});
}

TEST(SceneLoader, InextensibleEndsTooFarApart) {
  // 91.44 m of line cannot reach 100 m: an error for an inextensible line...
  const std::string far = With("position = [80.0, 30.48]", "position = [100.0, 0.0]");
  ExpectError(With("model = \"elastic\"", "model = \"inextensible\"", far), "ends.end.position",
              {"expected", "91.44"});
  // ... while an elastic one starts stretched (a warning, not an error) and solves.
  const SceneDef s = ParseScene(far, kFile);
  EXPECT_NO_THROW(SolveLineEquilibrium(LineOf(s)));
}

// Table files live next to the scene; these tests write them into a temporary folder.
class TableMotion : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("cablefilm_scene_test_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir_);
    scene_ = (dir_ / "ship_scene.toml").string();
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  void WriteFile(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
  }
  std::string TableScene(const std::string& file) {
    const std::string troch =
        "motion = \"trochoid\"\nx_amplitudes = [1.8288, 0.0]\ny_amplitudes = [0.0, 1.8288]\n"
        "period = 10.0\nramp_rate = 0.5\n";
    return With(troch, "motion = \"table\"\nfile = \"" + file + "\"\n");
  }
  std::filesystem::path dir_;
  std::string scene_;
};

// A file named as MoorDyn's are (.txt) that is neither a scene nor a MoorDyn file: the MoorDyn
// reader's complaint, as `cablefilm convert` gives it, not a TOML syntax error at its line 1
// (a tab-separated table of numbers was so reported).
TEST_F(TableMotion, TextFileThatIsNeitherSaysWhatMoorDynNeeds) {
  WriteFile("table.txt", "t\tx\n0\t4\n1\t5\n");
  try {
    LoadScene((dir_ / "table.txt").string());
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("no LINES section"), std::string::npos) << e.what();
  }
  WriteFile("table.toml", "t\tx\n0\t4\n");  // a scene's name: TOML's complaint
  try {
    LoadScene((dir_ / "table.toml").string());
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("not valid TOML"), std::string::npos) << e.what();
  }
}

TEST_F(TableMotion, GoodTableLoads) {
  WriteFile("ship.csv", "t,x,y\n0,0,0\n1,0.5,0.1\n2,0.2,-0.3\n");
  const SceneDef s = ParseScene(TableScene("ship.csv"), scene_);
  ASSERT_EQ(s.points[1].motion.table.size(), 3u);
  EXPECT_DOUBLE_EQ(s.points[1].motion.table[2][2], -0.3);
  const LineModel m = LineOf(s);
  EXPECT_NEAR(m.ends.end.Position(1.0).x(), 80.5, 1e-12);  // offsets from the rest position
}

TEST(SceneLoader, MinimumBreakingLoad) {
  // Optional: 0 (not given) by default; when given a positive force in N, on the link's model.
  EXPECT_EQ(ParseScene(kBase, "s.toml").materials[1].minimum_breaking_load, 0.0);
  const SceneDef s = ParseScene(
      With("name = \"nylon\"", "name = \"nylon\"\nminimum_breaking_load = 2.5e5"), "s.toml");
  EXPECT_EQ(s.materials[1].minimum_breaking_load, 2.5e5);
  const LineModel m = LineOf(s);
  EXPECT_EQ(m.line.breaking_load[0], 0.0);                  // wire: none
  EXPECT_EQ(m.line.breaking_load[m.line.links - 1], 2.5e5);  // nylon
  EXPECT_TRUE(m.line.has_breaking_load());
  for (const char* bad : {"0", "-1.0", "\"big\"", "1e16"})
    ExpectError(With("name = \"nylon\"",
                     std::string("name = \"nylon\"\nminimum_breaking_load = ") + bad),
                "material[1].minimum_breaking_load", {"expected a positive number in N"});
}

TEST_F(TableMotion, InterpolationKey) {
  WriteFile("ship.csv", "t,x,y\n0,0,0\n1,0.5,0.1\n2,0.2,-0.3\n");
  const std::string table = "motion = \"table\"\nfile = \"ship.csv\"\n";
  EXPECT_EQ(ParseScene(TableScene("ship.csv"), scene_).points[1].motion.interpolation,
            TableInterpolation::kSpline);  // the default
  const SceneDef s = ParseScene(
      With(table, table + "interpolation = \"linear\"\n", TableScene("ship.csv")), scene_);
  EXPECT_EQ(s.points[1].motion.interpolation, TableInterpolation::kLinear);
  // Built: straight between rows, 0.5 m/s of x from t = 0 to 1 s.
  const LineModel m = LineOf(s);
  EXPECT_NEAR(m.ends.end.Position(0.5).x(), 80.25, 1e-12);
  EXPECT_NEAR(m.ends.end.Velocity(0.5).x(), 0.5, 1e-12);
  ExpectError(With(table, table + "interpolation = \"cubic\"\n", TableScene("ship.csv")),
              "ends.end.interpolation", {"spline", "linear"}, scene_);
  // Only a table has it.
  ExpectError(With("motion = \"fixed\"\n", "motion = \"fixed\"\ninterpolation = \"linear\"\n"),
              "ends.start.interpolation", {"unknown key"}, scene_);
}

TEST_F(TableMotion, MissingTable) {
  ExpectError(TableScene("nope.csv"), "ends.end.file", {"nope.csv", "cannot open"}, scene_);
}

TEST_F(TableMotion, MalformedTables) {
  WriteFile("bad1.csv", "t,x,y\n0,0,0\n1,0.5\n");
  ExpectError(TableScene("bad1.csv"), "ends.end.file", {"bad1.csv:3", "expected three numbers"},
              scene_);
  WriteFile("bad2.csv", "0,0,0\n1,abc,0\n");
  ExpectError(TableScene("bad2.csv"), "ends.end.file", {"bad2.csv:2", "expected"}, scene_);
  WriteFile("bad3.csv", "0,0,0\n1,0,0\n1,1,0\n");
  ExpectError(TableScene("bad3.csv"), "ends.end.file", {"bad3.csv:3", "increase"}, scene_);
  WriteFile("bad4.csv", "t,x,y\n0,0,0\n");
  ExpectError(TableScene("bad4.csv"), "ends.end.file", {"at least two rows"}, scene_);
  WriteFile("bad5.csv", "0,0,0\n1,nan,0\n");
  ExpectError(TableScene("bad5.csv"), "ends.end.file", {"finite"}, scene_);
  ExpectError(With("motion = \"table\"\nfile = \"x.csv\"\n", "motion = \"table\"\n",
                   TableScene("x.csv")),
              "ends.end.file", {"missing"}, scene_);
}

TEST(SceneLoader, DefaultsApply) {
  const std::string minimal = R"(
[[material]]
name = "rope"
diameter = 0.02
area = 3e-4
mass_per_length = 1.0
youngs_modulus = 1e9

[[cable.section]]
material = "rope"
length = 10.0
segments = 10

[ends.start]
position = [0.0, 0.0]

[ends.end]
position = [8.0, 0.0]
)";
  const SceneDef s = ParseScene(minimal, "scenes/minimal.toml");
  EXPECT_EQ(s.title, "minimal");
  EXPECT_EQ(s.environment.current, 0.0);
  EXPECT_EQ(s.environment.gravity, 9.80665);
  EXPECT_EQ(s.environment.fluid_density, 1025.0);  // documented default: sea water
  EXPECT_TRUE(s.lines[0].weights.empty());
  EXPECT_EQ(s.initial, InitialStateKind::kEquilibrium);
  EXPECT_EQ(s.simulation.time_step, 0.0);  // "auto"
  EXPECT_EQ(s.lines[0].model, CableModelKind::kElastic);
  EXPECT_EQ(s.points[0].motion.motion, EndMotionKind::kFixed);
  EXPECT_EQ(s.points[1].motion.motion, EndMotionKind::kFixed);
  EXPECT_EQ(s.materials[0].drag_coefficient, 1.2);
  EXPECT_EQ(s.materials[0].added_mass_coefficient, 1.0);
  EXPECT_GT(s.output.interval, 0.0);
}

TEST(SceneLoader, ShippedScenesLoadBuildAndSolve) {
  for (const char* name : {"polachek1963", "catenary", "taut_string", "hanging_chain"}) {
    const std::string path = std::string(CABLEFILM_SOURCE_DIR) + "/scenes/" + name + ".toml";
    SceneDef s;
    ASSERT_NO_THROW(s = LoadScene(path)) << path;
    const LineModel m = LineOf(s);
    LineEquilibriumReport rep;
    EXPECT_NO_THROW(SolveLineEquilibrium(m, &rep)) << path;
    EXPECT_LE(rep.residual, 1e-6 * rep.force_scale) << path;
  }
  try {
    LoadScene("/nonexistent/dir/scene.toml");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/dir/scene.toml"), std::string::npos);
  }
}

// ---- Issue 11: every input answered with a file:line:key message, within stated limits ----

// Defect 1: an integer beyond 2^53 where a decimal is expected ended the program with
// std::bad_optional_access (toml++ has no exact double for it); every key gets a message.
TEST(SceneLoader, IntegersBeyond2To53GetAKeyMessage) {
  const std::string big = "9007199254740993";
  struct Case {
    std::string from, to, key;
  };
  const std::vector<Case> cases = {
      {"current = 0.0", "current = " + big, "environment.current"},
      {"gravity = 9.80665", "gravity = " + big, "environment.gravity"},
      {"fluid_density = 1025.0", "fluid_density = -" + big, "environment.fluid_density"},
      {"diameter = 0.0254", "diameter = " + big, "material[0].diameter"},
      {"youngs_modulus = 9.0e10", "youngs_modulus = " + big, "material[0].youngs_modulus"},
      {"length = 45.72", "length = " + big, "cable.section[0].length"},
      {"at = 27.432", "at = " + big, "cable.weight[0].at"},
      {"mass = 453.6", "mass = " + big, "cable.weight[0].mass"},
      {"position = [80.0, 30.48]", "position = [" + big + ", 30.48]", "ends.end.position"},
      {"x_amplitudes = [1.8288, 0.0]", "x_amplitudes = [1.8288, -" + big + "]",
       "ends.end.x_amplitudes"},
      {"period = 10.0", "period = " + big, "ends.end.period"},
      {"duration = 60.0", "duration = " + big, "simulation.duration"},
      {"time_step = \"auto\"", "time_step = " + big, "simulation.time_step"},
      {"film = false", "film = false\ninterval = " + big, "output.interval"},
  };
  for (const Case& c : cases) ExpectError(With(c.from, c.to), c.key, {"expected", big, "2^53"});
  ExpectError(kBase + "[film]\nfps = " + big + "\n", "film.fps", {big});
  ExpectError(kBase + "[film]\nspeed = " + big + "\n", "film.speed", {big});
  ExpectError(kBase + "[film]\ntension_range = [0, " + big + "]\n", "film.tension_range", {big});
  // Whole numbers up to 2^53 are numbers like any other (here: beyond a length's range).
  ExpectError(With("length = 45.72", "length = 9007199254740992"), "cable.section[0].length",
              {"from 1e-6 to 1e6", "got 9.0072e15"});
  EXPECT_EQ(ParseScene(With("current = 0.0", "current = 2"), kFile).environment.current, 2.0);
}

// Defect 7 (length = 1e308 gave "tolerance -nan"): every number has a stated range that keeps
// the model's arithmetic finite.
TEST(SceneLoader, NumbersHaveStatedRanges) {
  ExpectError(With("length = 45.72", "length = 1e308"), "cable.section[0].length",
              {"from 1e-6 to 1e6", "1e308"});
  ExpectError(With("length = 45.72", "length = 1e-300"), "cable.section[0].length", {"1e-6"});
  ExpectError(With("mass_per_length = 2.75", "mass_per_length = 1e300"),
              "material[0].mass_per_length", {"1e6"});
  ExpectError(With("youngs_modulus = 9.0e10", "youngs_modulus = 1e300"),
              "material[0].youngs_modulus", {"1e13"});
  ExpectError(With("current = 0.0", "current = -1e300"), "environment.current", {"-1000 to 1000"});
  ExpectError(With("position = [80.0, 30.48]", "position = [80.0, 1e7]"), "ends.end.position",
              {"-1e6 to 1e6"});
  ExpectError(With("y_amplitudes = [0.0, 1.8288]", "y_amplitudes = [0.0, 1e20]"),
              "ends.end.y_amplitudes", {"1e6"});
  ExpectError(With("mass = 453.6", "mass = 1e300"), "cable.weight[0].mass", {"1e9"});
  // The whole cable: at most 1e6 m and 1e7 links.
  ExpectError(With("length = 45.72\nsegments = 30", "length = 999999.0\nsegments = 30"),
              "cable.section[1].length", {"1e6"});
  ExpectError(With("segments = 30", "segments = 9000000", With("segments = 30", "segments = 9000000")),
              "cable.section[1].segments", {"1.8e7 links", "at most 1e7"});
}

// Defect 3: runs that quietly did nothing (counts overflowed) are refused, naming the key,
// the limit and why.
TEST(SceneLoader, RunCountsHaveLimits) {
  // duration = 1e18: the row count overflowed and 0 s were simulated with exit status 0.
  ExpectError(With("duration = 60.0", "duration = 1e18"), "simulation.duration", {"at most 1e9"});
  // Within its own range, but 3e10 rows at the default interval (one per film frame).
  ExpectError(With("duration = 60.0", "duration = 1e9"), "simulation.duration",
              {"rows", "at most 1e7"});
  // [output] interval = 1e-300: the same overflow.
  ExpectError(With("film = false", "film = false\ninterval = 1e-300"), "output.interval",
              {"6e301 rows", "at most 1e7", "at least 6e-6 s"});
  // An interval longer than the run: no row at all.
  ExpectError(With("film = false", "film = false\ninterval = 100.0"), "simulation.duration",
              {"shorter than one output interval", "100 s"});
  // time_step = 1e-11 was silently replaced by the output interval (the steps per output
  // overflowed an int): refused beyond 1e9 steps, and a step within the limit is kept.
  ExpectError(With("time_step = \"auto\"", "time_step = 1e-11"), "simulation.time_step",
              {"6e12 steps", "at most 1e9", "at least 6e-8 s"});
  const SceneDef fine = ParseScene(With("time_step = \"auto\"", "time_step = 1e-7"), kFile);
  EXPECT_EQ(fine.simulation.time_step, 1e-7);
  // Without an interval the rows follow the frames: named by the film key.
  ExpectError(With("film = false", "film = true") + "[film]\nspeed = 1e-300\n", "film.speed",
              {"rows"});
}

// The film's frame count is the film's: checked where a film is made (ResolveFilm, which
// `run`, `compare`, `check` and the Python module call), not by the loader, so that a run
// without its film (--no-film) is never refused for it.
void ExpectFilmError(const std::string& text, const std::string& key,
                     const std::vector<std::string>& expected) {
  const SceneDef scene = ParseScene(text, kFile);
  try {
    ResolveFilm(scene, {}, kCommandLineNames);
    ADD_FAILURE() << "no error for key " << key;
  } catch (const Error& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(std::string(kFile) + ": " + key + ": "), std::string::npos) << msg;
    for (const std::string& s : expected)
      EXPECT_NE(msg.find(s), std::string::npos) << "\"" << s << "\" not in: " << msg;
  }
}

TEST(SceneLoader, FilmFramesAreCountedForAFilmOnly) {
  // [film] speed = 1e-300 wrote a film of 0 frames and said "wrote film.mp4".
  const std::string film = With("film = false", "film = true\ninterval = 0.05");
  ExpectFilmError(film + "[film]\nspeed = 1e-300\n", "film.speed",
                  {"frames", "expected 1 to 1e6 frames", "a speed from 0.0018 to 1800"});
  ExpectFilmError(film + "[film]\nspeed = 1e5\n", "film.speed", {"make 0 frames"});
  // A long run with the scene's film on: 120000 s at 30 frames/s is 3.6e6 frames, too many
  // for a film, yet the scene loads (`run --no-film` runs it).
  const std::string longer = With("duration = 60.0", "duration = 120000.0",
                                  With("film = false", "film = true\ninterval = 1000.0"));
  EXPECT_NO_THROW(ParseScene(longer, kFile));
  ExpectFilmError(longer, "film.speed", {"3.6e6 frames", "expected 1 to 1e6 frames"});
  // No film: its frame count does not matter (but its keys' own ranges do).
  EXPECT_NO_THROW(ParseScene(With("film = false", "film = false\ninterval = 0.05") +
                                 "[film]\nspeed = 1e5\n",
                             kFile));
}

// A film of part of the run: its forms, each refusal naming what it takes; its fit to the run
// (within the run's 60 s) and its frame count are checked where a film is made.
TEST(SceneLoader, AFilmWindowIsAPeakWidthOrASpanWithinTheRun) {
  const FilmWindow peak = ParseScene(kBase + "[film]\nwindow = \"peak:20\"\n", kFile).film.window;
  EXPECT_EQ(peak.peak_width, 20.0);
  EXPECT_FALSE(peak.whole());
  const FilmWindow span = ParseScene(kBase + "[film]\nwindow = [10, 25.5]\n", kFile).film.window;
  EXPECT_EQ(span.start, 10.0);
  EXPECT_EQ(span.end, 25.5);
  EXPECT_EQ(ParseScene(kBase + "[film]\nwindow = \"10,25.5\"\n", kFile).film.window.end, 25.5);
  EXPECT_TRUE(ParseScene(kBase + "[film]\nwindow = \"whole\"\n", kFile).film.window.whole());
  EXPECT_TRUE(ParseScene(kBase, kFile).film.window.whole());
  for (const char* bad : {"\"peak:0\"", "\"peak:-5\"", "\"peak\"", "\"20,10\"", "\"a,b\"", "5"})
    ExpectError(kBase + "[film]\nwindow = " + bad + "\n", "film.window",
                {"expected \"peak:SECONDS\"", "[T0, T1]"});
  ExpectError(kBase + "[film]\nwindow = [20, 10]\n", "film.window", {"T1 > T0"});
  ExpectError(kBase + "[film]\nwindow = [-1, 10]\n", "film.window", {">= 0"});
  const std::string film = With("film = false", "film = true\ninterval = 0.05");
  ExpectFilmError(film + "[film]\nwindow = [10, 61]\n", "film.window",
                  {"expected a window within the run, from 0 to 60 s, got 10 to 61 s"});
  // Its frames are counted over its rows as the film takes them: 0.01 s around the peak is no
  // row either side at rows of 0.05 s; [0.1, 0.2] s at rows of 30 s is the first 30 s.
  ExpectFilmError(film + "[film]\nwindow = \"peak:0.01\"\n", "film.speed",
                  {"0 s simulated", "make 0 frames"});
  const std::string coarse = With("film = false", "film = true\ninterval = 30.0");
  ExpectFilmError(coarse + "[film]\nwindow = [0.1, 0.2]\nfps = 240\nspeed = 0.001\n", "film.speed",
                  {"30 s simulated", "7.2e6 frames"});
  EXPECT_NO_THROW(ResolveFilm(ParseScene(film + "[film]\nwindow = \"peak:600\"\n", kFile), {},
                              kCommandLineNames));  // wider than the run: the whole run
}

// Defect 6: film settings that only failed in run, after the whole simulation (libx264), are
// refused by the loader, so `check` catches them.
TEST(SceneLoader, FilmRatesHaveStatedRanges) {
  for (const char* fps : {"1e12", "1e300", "1e-300", "0.5", "241", "0"})
    ExpectError(kBase + "[film]\nfps = " + fps + "\n", "film.fps", {"from 1 to 240"});
  EXPECT_EQ(ParseScene(kBase + "[film]\nfps = 240\n", kFile).film.fps, 240.0);
  // No interval given: fps = 1e12 wrote a row every 1e-12 s (650 MB of CSV a minute).
  ExpectError(With("film = false", "film = true") + "[film]\nfps = 1e12\n", "film.fps",
              {"240"});
  ExpectError(kBase + "[film]\nwidth = 65536\n", "film.width", {"16 to 7680"});
  ExpectError(kBase + "[film]\nheight = 99999999998\n", "film.height", {"16 to 4320"});
  ExpectError(kBase + "[film]\ncolormap = \"jet\"\n", "film.colormap", {"viridis"});
}

// Defect 7: an inextensible cable exactly as long as its ends are apart passed `check` (>)
// and failed `run` (>=); both refuse it now.
TEST(SceneLoader, InextensibleEndsExactlyTheLengthApart) {
  const std::string inext = With("model = \"elastic\"", "model = \"inextensible\"");
  ExpectError(With("position = [80.0, 30.48]", "position = [91.44, 0.0]", inext),
              "ends.end.position", {"less than the cable's length", "91.44"});
  EXPECT_NO_THROW(ParseScene(With("position = [80.0, 30.48]", "position = [91.4, 0.0]", inext),
                             kFile));
}

// Defect 7: elastic ends so far apart that a link starts beyond twice its length passed
// `check` with a warning, then `run` said "numerical blow-up at t = 0".
TEST(SceneLoader, ElasticEndsTooFarApartForTheModel) {
  // Straight start: every link stretched alike, 210 m / 91.44 m = 2.3.
  const std::string far = With("position = [80.0, 30.48]", "position = [210.0, 0.0]");
  const SceneDef straight = ParseScene(far + "[initial]\nstate = \"straight\"\n", kFile);
  try {
    CheckModelLimits(straight, BuildModel(straight));
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(std::string(kFile) + ": ends.end.position"), std::string::npos) << msg;
    EXPECT_NE(msg.find("2.29659 times"), std::string::npos) << msg;
  }
  // Equilibrium start: the nylon section (EA 4.05e6 N against the wire's 4.56e7 N) takes
  // nearly all the stretch: at 150 m (1.64 x the length) its links are at 2.18 x theirs.
  const SceneDef eq = ParseScene(With("position = [80.0, 30.48]", "position = [150.0, 0.0]"),
                                 kFile);
  EXPECT_THROW(CheckModelLimits(eq, BuildModel(eq)), Error);
  // Stretched but within the limit: a warning in `check`, no error.
  const SceneDef ok = ParseScene(With("position = [80.0, 30.48]", "position = [120.0, 0.0]"),
                                 kFile);
  EXPECT_NO_THROW(CheckModelLimits(ok, BuildModel(ok)));
  // The model-level check of an inextensible line agrees with its equilibrium (>=).
  SceneDef inext = ParseScene(kBase, kFile);
  inext.lines[0].model = CableModelKind::kInextensible;
  inext.points[1].motion.position = {91.44, 0.0};
  EXPECT_THROW(CheckModelLimits(inext, BuildModel(inext)), Error);
}

// Defect 7: a scene path that is a directory said "material: missing"; defect 5: a scene
// that is /dev/zero grew memory without bound.
TEST(SceneLoader, SceneFileThatIsADirectoryOrEndless) {
  const std::string dir = ::testing::TempDir();
  try {
    LoadScene(dir);
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("is a directory"), std::string::npos) << e.what();
  }
  try {
    LoadScene("/dev/zero");
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("larger than 16 MiB"), std::string::npos) << e.what();
  }
}

// Defect 8: input text in messages is escaped (keys, names, the TOML parser's own words).
TEST(SceneLoader, MessagesEscapeInputText) {
  auto message = [](const std::string& text) {
    try {
      ParseScene(text, kFile);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string key = message(kBase + "\"\\u001b[2J\\u001b]0;x\\u0007\" = 1\n");
  EXPECT_EQ(key.find('\x1b'), std::string::npos) << key;
  EXPECT_NE(key.find("\\x1B[2J\\x1B]0;x\\x07"), std::string::npos) << key;
  const std::string name =
      message(With("material = \"nylon\"", "material = \"ny\\u009b31mlon\\u202e\""));
  EXPECT_NE(name.find("\"ny\\u{009B}31mlon\\u{202E}\""), std::string::npos) << name;
  const std::string raw = message(With("title = \"base\"", "title = \"a\x1b[31m\""));
  EXPECT_EQ(raw.find('\x1b'), std::string::npos) << raw;
  const std::string path = [&] {
    try {
      ParseScene("colour = 1\n", "scene\x1b[31m.toml");
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string();
  }();
  EXPECT_EQ(path.rfind("scene\\x1B[31m.toml:1: material: missing", 0), 0u) << path;
}

// Defect 5: a motion table has stated limits, checked while reading (/dev/zero grew memory at
// 0.5 GB/s until killed).
TEST_F(TableMotion, SizeLimits) {
  ExpectError(TableScene("/dev/zero"), "ends.end.file", {"/dev/zero:1", "longer than 1024"},
              scene_);
  {
    std::ofstream out(dir_ / "long.csv");
    out << "t,x,y\n";
    for (long i = 0; i <= kMaxTableRows; ++i) out << i << ",0,0\n";
  }
  ExpectError(TableScene("long.csv"), "ends.end.file", {"long.csv:1000002", "more than 1e6 rows"},
              scene_);
  {
    std::ofstream out(dir_ / "huge.csv");
    const std::string comment = "#" + std::string(1000, 'x') + "\n";
    for (std::uintmax_t n = 0; n <= kMaxTableBytes; n += comment.size()) out << comment;
  }
  ExpectError(TableScene("huge.csv"), "ends.end.file", {"larger than 64 MiB"}, scene_);
}

// Defect 7: a table path that is a directory said "expected at least two rows".
TEST_F(TableMotion, TableThatIsADirectory) {
  std::filesystem::create_directories(dir_ / "ship.csv");
  ExpectError(TableScene("ship.csv"), "ends.end.file", {"ship.csv: is a directory"}, scene_);
}

// Defect 8: tables are read strictly: a header row exactly "t,x,y" or none (said which), three
// decimal numbers a row; a malformed first row was skipped as a header, trailing commas and
// hexadecimal floats were taken.
TEST_F(TableMotion, StrictRows) {
  WriteFile("zz.csv", "0,zz,0\n1,0,0\n2,0,0\n");
  ExpectError(TableScene("zz.csv"), "ends.end.file",
              {"zz.csv:1", "expected a header row exactly \"t,x,y\" or \"t,x,y,z\", or numbers", "0,zz,0"},
              scene_);
  WriteFile("comma.csv", "t,x,y\n0,0,0,\n1,0,0\n");
  ExpectError(TableScene("comma.csv"), "ends.end.file",
              {"comma.csv:2", "after the header row", "\"0,0,0,\""}, scene_);
  WriteFile("hex.csv", "0,0,0\n0x1p0,0,0\n");
  ExpectError(TableScene("hex.csv"), "ends.end.file",
              {"hex.csv:2", "no header row", "0x1p0"}, scene_);
  WriteFile("inf.csv", "0,0,0\n1,inf,0\n");
  ExpectError(TableScene("inf.csv"), "ends.end.file", {"inf.csv:2", "finite"}, scene_);
  WriteFile("empty_cell.csv", "0,0,0\n1,,0\n");
  ExpectError(TableScene("empty_cell.csv"), "ends.end.file", {"empty_cell.csv:2"}, scene_);
  WriteFile("spaced_header.csv", "t, x, y\n0,0,0\n1,0,0\n");
  ExpectError(TableScene("spaced_header.csv"), "ends.end.file", {"spaced_header.csv:1"}, scene_);
  WriteFile("late_header.csv", "0,0,0\nt,x,y\n1,0,0\n");
  ExpectError(TableScene("late_header.csv"), "ends.end.file", {"late_header.csv:2"}, scene_);
  WriteFile("far.csv", "0,0,0\n1,2e6,0\n");
  ExpectError(TableScene("far.csv"), "ends.end.file", {"far.csv:2", "1e6"}, scene_);
  WriteFile("one.csv", "t,x,y\n0,0,0\n");
  ExpectError(TableScene("one.csv"), "ends.end.file",
              {"at least two rows", "after the header row", "found 1"}, scene_);
  WriteFile("escape.csv", "0,0,0\n1,\x1b[2J\xff,0\n");
  try {
    ParseScene(TableScene("escape.csv"), scene_);
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    const std::string msg = e.what();
    EXPECT_EQ(msg.find('\x1b'), std::string::npos) << msg;
    EXPECT_NE(msg.find("\"1,\\x1B[2J\\xFF,0\""), std::string::npos) << msg;
  }
  // What is allowed: a header or none, blanks around numbers, signs and exponents, CRLF line
  // ends, blank lines and comments.
  WriteFile("ok1.csv", "t,x,y\r\n0,0,0\r\n\r\n# pause\r\n1.5, -2.5e-1 ,+3E2\r\n.5e1,1.,0\n");
  const SceneDef s = ParseScene(TableScene("ok1.csv"), scene_);
  ASSERT_EQ(s.points[1].motion.table.size(), 3u);
  EXPECT_EQ(s.points[1].motion.table[1][1], -0.25);
  EXPECT_EQ(s.points[1].motion.table[1][2], 300.0);
  EXPECT_EQ(s.points[1].motion.table[2][0], 5.0);
  WriteFile("ok2.csv", "0,0,0\n1,0.5,0.1");  // no header, no final newline
  EXPECT_EQ(ParseScene(TableScene("ok2.csv"), scene_).points[1].motion.table.size(), 2u);
}

// ---------------------------------------------------------------------------------------------
// Issue 10: [seabed] and a current profile.

TEST(SceneLoader, SeabedLoadsWithDefaults) {
  const SceneDef s = ParseScene(kBase + "\n[seabed]\ny = -2.5\n", kFile);
  ASSERT_TRUE(s.seabed.present);
  EXPECT_EQ(s.seabed.y, -2.5);
  EXPECT_EQ(s.seabed.stiffness, 3e7);     // N/m per m of line
  EXPECT_LT(s.seabed.damping, 0);         // critical for each station
  EXPECT_EQ(s.seabed.friction, 0.0);
  EXPECT_EQ(s.seabed.friction_velocity, 0.01);
  EXPECT_EQ(s.seabed.friction_model, FrictionModel::kStickSlip);
  EXPECT_LT(s.seabed.friction_stiffness, 0);  // the normal stiffness
  const LineModel m = LineOf(s);
  ASSERT_TRUE(m.env.seabed.present);
  // Station 1: half of each of its two links of 45.72 / 30 m.
  EXPECT_DOUBLE_EQ(m.line.seabed_stiffness[1], 3e7 * 45.72 / 30);
  EXPECT_GT(m.line.seabed_damping[1], 0);
  EXPECT_FALSE(ParseScene(kBase, kFile).seabed.present);  // no table, no seabed
  const SceneDef t = ParseScene(kBase + "\n[seabed]\ny = 0\nstiffness = 1e6\ndamping = 2e3\n"
                                        "friction = 0.6\nfriction_velocity = 0.05\n",
                                kFile);
  EXPECT_EQ(t.seabed.y, 0.0);  // the anchor may rest on it
  EXPECT_EQ(t.seabed.stiffness, 1e6);
  EXPECT_EQ(t.seabed.damping, 2e3);
  EXPECT_EQ(t.seabed.friction, 0.6);
  EXPECT_EQ(t.seabed.friction_velocity, 0.05);
  // Giving friction_velocity asks for the smoothed law (scenes written before stick-slip).
  EXPECT_EQ(t.seabed.friction_model, FrictionModel::kSmoothed);
  EXPECT_DOUBLE_EQ(LineOf(t).line.seabed_damping[1], 2e3 * 45.72 / 30);
  // Stick-slip by name, with its own shear stiffness: the spring per station is K l_j and the
  // dashpot keeps the normal one's ratio to critical, c_j sqrt(K / k).
  const SceneDef u = ParseScene(kBase + "\n[seabed]\ny = 0\nstiffness = 1e6\ndamping = 2e3\n"
                                        "friction = 0.6\nfriction_velocity = 0.05\n"
                                        "friction_model = \"stick_slip\"\n"
                                        "friction_stiffness = 4e6\n",
                                kFile);
  EXPECT_EQ(u.seabed.friction_model, FrictionModel::kStickSlip);
  const LineModel mu = LineOf(u);
  EXPECT_DOUBLE_EQ(mu.line.friction_stiffness[1], 4e6 * 45.72 / 30);
  EXPECT_DOUBLE_EQ(mu.line.friction_damping[1], 2.0 * 2e3 * 45.72 / 30);
}

TEST(SceneLoader, SeabedErrors) {
  ExpectError(kBase + "\n[seabed]\nstiffness = 1e7\n", "seabed.y", {"missing"});
  // The line of y: after kBase's lines, a blank one and [seabed].
  const std::string line =
      ":" + std::to_string(std::count(kBase.begin(), kBase.end(), '\n') + 3) + ":";
  ExpectError(kBase + "\n[seabed]\ny = 0.5\n", "seabed.y",
              {"above the start end", "ends.start.position y = 0 m", line});
  // The trochoid end goes down to 30.48 - 1.8288 m.
  ExpectError(With("position = [0.0, 0.0]", "position = [0.0, 40.0]") + "\n[seabed]\ny = 29\n",
              "seabed.y", {"above the end end", "down to 28.6512 m as it moves"});
  ExpectError(kBase + "\n[seabed]\ny = -1\nstiffness = 0\n", "seabed.stiffness",
              {"N/m per m of line", "from 1 to 1e12"});
  ExpectError(kBase + "\n[seabed]\ny = -1\ndamping = -3\n", "seabed.damping", {">= 0"});
  ExpectError(kBase + "\n[seabed]\ny = -1\nfriction = 11\n", "seabed.friction",
              {"Coulomb", "at most 10"});
  ExpectError(kBase + "\n[seabed]\ny = -1\nfriction_velocity = 0\n", "seabed.friction_velocity",
              {"m/s", "1e-9 to 1000"});
  ExpectError(kBase + "\n[seabed]\ny = -1\nfriction_model = \"coulomb\"\n",
              "seabed.friction_model", {"stick_slip", "smoothed"});
  ExpectError(kBase + "\n[seabed]\ny = -1\nfriction_stiffness = 0\n", "seabed.friction_stiffness",
              {"N/m per m of line", "from 1 to 1e12"});
  ExpectError(kBase + "\n[seabed]\ny = -1\nfrction = 0.5\n", "seabed.frction", {"unknown key"});
  ExpectError(kBase + "\n[seabed]\ny = \"deep\"\n", "seabed.y", {"elevation in m"});
  ExpectError("seabed = 3\n" + kBase, "seabed", {"expected a table"});
}

TEST(SceneLoader, CurrentProfile) {
  const SceneDef s =
      ParseScene(With("current = 0.0", "current = [[-10, 0.2], [0.0, 1.0], [5, 1.5]]"), kFile);
  ASSERT_EQ(s.environment.current_profile.y.size(), 3u);
  EXPECT_EQ(s.environment.current, 0.0);
  const LineModel m = LineOf(s);
  EXPECT_DOUBLE_EQ(CurrentAt(m, SceneWater(m), -5.0).x(), 0.6);
  EXPECT_DOUBLE_EQ(CurrentAt(m, SceneWater(m), -50.0).x(), 0.2);
  EXPECT_DOUBLE_EQ(CurrentAt(m, SceneWater(m), 50.0).x(), 1.5);
  // One pair: a uniform current written as a table.
  const LineModel one = LineOf(ParseScene(With("current = 0.0", "current = [[3, -0.4]]"), kFile));
  EXPECT_DOUBLE_EQ(CurrentAt(one, SceneWater(one), -20.0).x(), -0.4);
  const std::string key = "environment.current";
  ExpectError(With("current = 0.0", "current = []"), key, {"from 1 to 10000 pairs", "got 0"});
  ExpectError(With("current = 0.0", "current = [[0, 1, 2]]"), key + "[0]", {"[y, speed]"});
  // A flat array is a horizontal vector [u, w]; one of another size names both forms.
  ExpectError(With("current = 0.0", "current = [3]"), key,
              {"[u, w]", "[[y, speed], ...]", "got an array of 1 numbers"});
  ExpectError(With("current = 0.0", "current = [3, 0, 1]"), key, {"[u, w]"});
  ExpectError(With("current = 0.0", "current = [[0, 1], [0, 2]]"), key + "[1]",
              {"increase strictly", "y = 0 m after 0 m"});
  ExpectError(With("current = 0.0", "current = [[0, 1], [-1, 2]]"), key + "[1]",
              {"increase strictly"});
  ExpectError(With("current = 0.0", "current = [[0, 1e4]]"), key + "[0]",
              {"speed in m/s", "-1000 to 1000"});
  ExpectError(With("current = 0.0", "current = [[2e6, 1]]"), key + "[0]", {"elevation in m"});
  ExpectError(With("current = 0.0", "current = [[0, nan]]"), key + "[0]", {"non-finite"});
  ExpectError(With("current = 0.0", "current = [[0, \"fast\"]]"), key + "[0]", {"speed in m/s"});
  ExpectError(With("current = 0.0", "current = \"fast\""), key,
              {"a speed in m/s", "or a profile [[y, speed], ...]"});
}

// ramp_rate = 1e-308 (above 0, as documented) made the start last 5 / nu = inf s, written as
// start_end = inf into run_report.toml: a ramp is from kMinRampRate (1e-9 1/s, slower than any
// run the loader takes) to kMaxRampRate, ends and waves alike.
TEST(SceneLoader, RampRatesKeepTheStartFinite) {
  for (const char* tiny : {"1e-308", "1e-300", "9.9e-10"}) {
    ExpectError(With("ramp_rate = 0.5", std::string("ramp_rate = ") + tiny), "ends.end.ramp_rate",
                {"expected a positive number in 1/s from 1e-9 to 1e6", std::string("got ") + tiny});
    ExpectError(kBase + "\n[waves]\nheight = 2\nperiod = 8\ndepth = 50\nramp_rate = " + tiny +
                    "\n",
                "waves.ramp_rate", {"from 1e-9 to 1e6"});
  }
  const SceneDef slowest = ParseScene(With("ramp_rate = 0.5", "ramp_rate = 1e-9"), kFile);
  EXPECT_EQ(slowest.points[1].motion.ramp_rate, kMinRampRate);
}

// Issue 10, part 3: [waves], and an end that follows them.
TEST(SceneLoader, Waves) {
  const SceneDef s = ParseScene(kBase + "\n[waves]\nheight = 2\nperiod = 8\ndepth = 50\n", kFile);
  ASSERT_TRUE(s.waves.present);
  EXPECT_EQ(s.waves.surface_y, 0.0);     // default: the still water level at y = 0
  EXPECT_EQ(s.waves.phase, 0.0);         // degrees
  EXPECT_EQ(s.waves.ramp_rate, 0.5);     // 4 / T
  const LineModel m = LineOf(s);
  ASSERT_TRUE(m.has_waves());
  EXPECT_DOUBLE_EQ(m.env.wave.k, WaveNumber(2 * M_PI / 8, 9.80665, 50));
  EXPECT_FALSE(LineOf(ParseScene(kBase, kFile)).has_waves());  // no table, no waves
  // The depth defaults to the still water level's height above the seabed.
  const SceneDef d = ParseScene(kBase + "\n[seabed]\ny = -10\n\n[waves]\nheight = 1\nperiod = 8"
                                        "\nsurface_y = 40\nphase = -90\nramp_rate = 0.1\n", kFile);
  EXPECT_EQ(d.waves.depth, 50.0);
  EXPECT_EQ(d.waves.ramp_rate, 0.1);
  EXPECT_DOUBLE_EQ(LineOf(d).env.wave.spec.phase, -M_PI / 2);
  // motion = "wave": x_rao = [1, 90], y_rao = [1, 0] is the water particle at the surface:
  // heave the surface elevation at the end's x, surge a cos(theta + 90 deg).
  const std::string wave_end =
      With("motion = \"trochoid\"\nx_amplitudes = [1.8288, 0.0]\ny_amplitudes = [0.0, 1.8288]\n"
           "period = 10.0\nramp_rate = 0.5",
           "motion = \"wave\"\nx_rao = [1.0, 90.0]\ny_rao = [1.0, 0.0]") +
      "\n[waves]\nheight = 2\nperiod = 8\ndepth = 50\nsurface_y = 35\nphase = 30\n";
  const SceneDef w = ParseScene(wave_end, kFile);
  EXPECT_TRUE(w.points[1].motion.follows_wave);
  const LineModel mw = LineOf(w);
  for (double t : {100.0, 103.3, 107.9}) {  // the ramp complete (R = 1 - 5e-16)
    const Vec p = mw.ends.end.Position(t) - mw.ends.end.rest();
    const double theta = mw.env.wave.k * 80.0 - mw.env.wave.omega * t + M_PI / 6;
    EXPECT_NEAR(p.y(), SurfaceAt(mw.env.wave, InPlane(80.0, 0.0), t) - 35.0, 1e-12);
    EXPECT_NEAR(p.x(), std::cos(theta + M_PI / 2), 1e-12);
  }
}

TEST(SceneLoader, WaveErrors) {
  ExpectError(kBase + "\n[waves]\nheight = 2\nperiod = 8\n", "waves.depth", {"missing"});
  ExpectError(kBase + "\n[waves]\nperiod = 8\ndepth = 50\n", "waves.height", {"missing"});
  // Deep water: 20 m at 5 s (L = 39 m) is H / L = 0.51, far beyond 1/7.
  ExpectError(kBase + "\n[waves]\nheight = 20\nperiod = 5\ndepth = 50\n", "waves.height",
              {"the wave breaks", "H / L = 0.51", "at most 5.57", "Miche"});
  // Shallow water: 2 m at 20 s in 2 m of water (L = 88 m, H / L = 0.023 < 1/7) breaks on the
  // depth: tanh(kh) / 7 = 0.020.
  ExpectError(kBase + "\n[waves]\nheight = 2\nperiod = 20\ndepth = 2\n", "waves.height",
              {"the wave breaks", "k h = 0.14"});
  ExpectError(kBase + "\n[waves]\nheight = 1\nperiod = 0\ndepth = 50\n", "waves.period",
              {"in s"});
  ExpectError(kBase + "\n[waves]\nheight = 1\nperiod = 8\ndepth = 50\nphase = 400\n",
              "waves.phase", {"degrees", "-360 to 360"});
  ExpectError(kBase + "\n[waves]\nheight = 1\nperiod = 8\ndepth = 50\nhieght = 2\n",
              "waves.hieght", {"unknown key"});
  ExpectError(kBase + "\n[seabed]\ny = -1\n\n[waves]\nheight = 1\nperiod = 8\nsurface_y = -5\n",
              "waves.surface_y", {"above the seabed"});
  const std::string wave_end = With("motion = \"trochoid\"", "motion = \"wave\"");
  ExpectError(wave_end, "ends.end.motion", {"[waves]"});
  ExpectError(With("motion = \"trochoid\"\nx_amplitudes = [1.8288, 0.0]",
                   "motion = \"wave\"\nx_rao = [-1.0, 0.0]\nx_amplitudes = [1.8288, 0.0]") +
                  "\n[waves]\nheight = 2\nperiod = 8\ndepth = 50\n",
              "ends.end.x_rao", {"amplitude ratio"});
}

// Issue 22 item 6: waves.depth was never compared with surface_y - seabed.y (a surface 100 m
// below the seabed ran with the whole line in air, exit 0), and a depth of 1e-300 printed NaN.
TEST(SceneLoader, WaveDepthAgainstTheSeabed) {
  // The message names the file, the line and the key, holds every piece of `expected`, and no
  // NaN.
  auto refused = [](const std::string& text, const std::string& key,
                    const std::vector<std::string>& expected) {
    try {
      ParseScene(text, kFile);
      ADD_FAILURE() << "no error for " << key;
    } catch (const Error& e) {
      const std::string msg = e.what();
      EXPECT_TRUE(std::regex_search(msg, std::regex(std::string("^") + kFile + ":[0-9]+: " +
                                                     std::regex_replace(key, std::regex("[.]"),
                                                                        "\\.") +
                                                     ": ")))
          << msg;
      for (const std::string& s : expected)
        EXPECT_NE(msg.find(s), std::string::npos) << "\"" << s << "\" not in: " << msg;
      std::string lower = msg;
      std::transform(lower.begin(), lower.end(), lower.begin(), ::tolower);
      EXPECT_EQ(lower.find("nan"), std::string::npos) << msg;
      EXPECT_EQ(lower.find("inf"), std::string::npos) << msg;
    }
  };
  const std::string bed = kBase + "\n[seabed]\ny = -10\n\n[waves]\nheight = 1\nperiod = 8\n";
  // The surface 100 m below the seabed, with the depth given (as the report's scene) or not.
  refused(bed + "depth = 100\nsurface_y = -110\n", "waves.surface_y",
          {"at least 0.001 m above the seabed (seabed.y = -10 m)", "100 m below it"});
  refused(bed + "surface_y = -110\n", "waves.surface_y", {"100 m below it"});
  refused(bed + "surface_y = -10\n", "waves.surface_y", {"0 m above it"});
  refused(bed + "surface_y = -9.9999999\n", "waves.surface_y", {"at least 0.001 m"});
  // A depth that is not the water's over the bed.
  refused(bed + "depth = 30\nsurface_y = 40\n", "waves.depth",
          {"surface_y - seabed.y = 40 - (-10) = 50 m (to 1e-6 of it), got 30 m",
           "or leave depth out"});
  refused(bed + "depth = 50.001\nsurface_y = 40\n", "waves.depth", {"got 50.001 m"});
  refused(bed + "depth = 1e-300\nsurface_y = 40\n", "waves.depth", {"from 0.001 to 1e6"});
  // Without a seabed the depth stands alone; 1e-300 m underflowed the dispersion relation.
  const std::string open_sea = kBase + "\n[waves]\nheight = 0\nperiod = 8\n";
  refused(open_sea + "depth = 1e-300\n", "waves.depth", {"from 0.001 to 1e6, got 1e-300"});
  refused(With("gravity = 9.80665", "gravity = 1e-300") +
              "\n[waves]\nheight = 0\nperiod = 0.001\ndepth = 1e6\n",
          "waves.period", {"no finite wave length", "environment.gravity = 1e-300"});
  // Consistent depths load: equal, within the tolerance, or left to the default.
  EXPECT_EQ(ParseScene(bed + "depth = 50\nsurface_y = 40\n", kFile).waves.depth, 50.0);
  EXPECT_EQ(ParseScene(bed + "depth = 50.00001\nsurface_y = 40\n", kFile).waves.depth, 50.00001);
  EXPECT_EQ(ParseScene(bed + "surface_y = 40\n", kFile).waves.depth, 50.0);
  EXPECT_EQ(ParseScene(open_sea + "depth = 0.001\n", kFile).waves.depth, 0.001);
}

// Issue 22 item 9: a 1 MB title cost 21 s and 420 MB of film, a 10 MB one needed SIGKILL. A
// title is at most 200 characters (UTF-8 characters, not bytes), refused with its line.
TEST(SceneLoader, TitleHasALengthLimit) {
  auto titled = [](const std::string& title) {
    return With("title = \"base\"", "title = \"" + title + "\"");
  };
  std::string accented;
  for (int i = 0; i < 200; ++i) accented += "\u00e9";  // 400 bytes
  EXPECT_EQ(ParseScene(titled(accented), kFile).title, accented);
  EXPECT_EQ(ParseScene(titled(std::string(200, 'x')), kFile).title, std::string(200, 'x'));
  for (const std::size_t n : {201ul, 1000000ul}) {
    try {
      ParseScene(titled(std::string(n, 'x')), kFile);
      ADD_FAILURE() << "a title of " << n << " characters was taken";
    } catch (const Error& e) {
      EXPECT_EQ(std::string(e.what()),
                std::string(kFile) + ":1: title: expected a title of at most 200 characters (it "
                                     "is drawn on one line of the film), got " +
                    std::to_string(n));
    }
  }
  // The default title (the file's name) is not the user's text: not refused.
  EXPECT_EQ(ParseScene(With("title = \"base\"\n", ""), std::string(220, 'n') + ".toml").title,
            std::string(220, 'n'));
}

}  // namespace
}  // namespace cablefilm

namespace cablefilm {
namespace {

// A system of two lines and three points (issue 20), for the system's errors.
const std::string kSystem = R"(
[[material]]
name = "chain"
diameter = 0.1
area = 0.0078
mass_per_length = 60.0
youngs_modulus = 5e10

[[point]]
name = "anchor"
position = [0.0, -60.0, 0.0]

[[point]]
name = "clump"
motion = "free"
position = [45.0, -40.0, 5.0]
mass = 3000.0

[[point]]
name = "fairlead"
position = [70.0, 0.0, 10.0]

[[line]]
name = "lower"
start = "anchor"
end = "clump"
[[line.section]]
material = "chain"
length = 60.0
segments = 24

[[line]]
name = "upper"
start = "clump"
end = "fairlead"
[[line.section]]
material = "chain"
length = 45.0
segments = 18
)";

std::string SystemWith(const std::string& from, const std::string& to) {
  return With(from, to, kSystem);
}

// A system runs as a line does: either scheme, from its equilibrium or its straight chords.
TEST(SceneLoader, SystemTakesEverySchemeAndStart) {
  const SceneDef s = ParseScene(kSystem + "\n[simulation]\nintegrator = \"explicit\"\n[initial]\n"
                                "state = \"straight\"\n", kFile);
  EXPECT_EQ(s.simulation.integrator, IntegratorChoice::kExplicit);
  EXPECT_EQ(s.initial, InitialStateKind::kStraight);
}

TEST(SceneLoader, SystemLoads) {
  const SceneDef s = ParseScene(kSystem, kFile);
  ASSERT_EQ(s.points.size(), 3u);
  ASSERT_EQ(s.lines.size(), 2u);
  EXPECT_EQ(s.lines[1].key, "line[1]");
  EXPECT_EQ(s.lines[1].start, 1);
  EXPECT_EQ(s.lines[1].end, 2);
  EXPECT_EQ(s.points[1].motion.motion, EndMotionKind::kFree);
  EXPECT_EQ(s.points[1].mass, 3000.0);
  EXPECT_EQ(s.lines[0].sections[0].segments, 24);
}

TEST(SceneLoader, SystemErrors) {
  ExpectError(kSystem + "\n[cable]\n", "cable", {"either one line", "this one has both"});
  ExpectError(SystemWith("end = \"clump\"", "end = \"clamp\""), "line[0].end",
              {"no point is named \"clamp\""});
  // A line from a point back to itself (a fuzzed scene's: its statics crawled for seconds).
  ExpectError(SystemWith("start = \"anchor\"", "start = \"clump\""), "line[0].end",
              {"expected another point than its start, \"clump\""});
  ExpectError(SystemWith("name = \"fairlead\"", "name = \"clump\""), "point[2].name",
              {"unique name"});
  ExpectError(SystemWith("name = \"upper\"", "name = \"lower\""), "line[1].name",
              {"unique name"});
  ExpectError(SystemWith("name = \"lower\"", "name = \"../lower\""), "line[0].name",
              {"letters, digits"});
  // A fixed point has no mass: the key of another motion is unknown.
  ExpectError(SystemWith("position = [0.0, -60.0, 0.0]", "position = [0.0, -60.0, 0.0]\nmass = 1.0"),
              "point[0].mass", {"unknown key"});
  ExpectError(SystemWith("mass = 3000.0", "mass = 3000.0\nforce = [1.0, \"x\"]"), "point[1].force",
              {"expected"});
  // A line's model: elastic or inextensible (the model refuses an inextensible line joined to
  // others: tests/core/coupled_island_test.cpp).
  ExpectError(SystemWith("name = \"lower\"", "name = \"lower\"\nmodel = \"rigid\""),
              "line[0].model", {"elastic", "inextensible"});
  ExpectError(SystemWith("segments = 18", "segments = 0"), "line[1].section[0].segments",
              {"expected"});
}

// The system with its fairlead on a free body.
const std::string kBodyPoint = R"([[body]]
name = "buoy"
motion = "free"
position = [70.0, 0.0, 10.0]
orientation = [0.0, 90.0, 0.0]
mass = 2.0e4
volume = 30.0
inertia = [1.0e5, 2.0e5]
added_mass = [1.0, 2.0, 3.0, 4.0, 5.0, 6.0]
initial_offset = [1.0, 0.0, 0.0, 0.0, 0.0, 10.0]

[[point]]
name = "fairlead"
body = "buoy"
position = [2.0, -1.0, 0.0])";

std::string BodySystem() {
  return SystemWith("[[point]]\nname = \"fairlead\"\nposition = [70.0, 0.0, 10.0]", kBodyPoint);
}

TEST(SceneLoader, AxialStiffnessIsEATimesTheArea) {
  // Material 1 of the base scene: E = 2e9 Pa on its area; written as EA instead, the same
  // links (to round-off: E = EA / area).
  const SceneDef base = ParseScene(kBase, kFile);
  const double area = base.materials[1].area, E = base.materials[1].youngs_modulus;
  const std::string ea = "axial_stiffness = " + FormatNumber(E * area);
  const SceneDef s = ParseScene(With("youngs_modulus = 2.0e9", ea), kFile);
  EXPECT_NEAR(s.materials[1].youngs_modulus, E, 1e-15 * E);
  const LineModel a = LineOf(base), b = LineOf(s);
  for (int j = 0; j < a.line.links; ++j)
    EXPECT_NEAR(b.line.axial_stiffness[j], a.line.axial_stiffness[j], 1e-14 * a.line.axial_stiffness[j]);
  ExpectError(With("youngs_modulus = 2.0e9", "youngs_modulus = 2.0e9\n" + ea),
              "material[1].axial_stiffness", {"not both"});
  ExpectError(With("youngs_modulus = 2.0e9\n", ""), "material[1].youngs_modulus",
              {"missing", "axial_stiffness"});
  ExpectError(With("youngs_modulus = 2.0e9", "axial_stiffness = -3.0"),
              "material[1].axial_stiffness", {"expected"});
}

TEST(SceneLoader, BodyLoads) {
  const SceneDef s = ParseScene(BodySystem(), kFile);
  ASSERT_EQ(s.bodies.size(), 1u);
  EXPECT_TRUE(s.bodies[0].free);
  EXPECT_EQ(s.points[2].body, 0);
  EXPECT_EQ(s.points[2].motion.position[0], 2.0);
  EXPECT_EQ(s.bodies[0].inertia[2], 1.0e5);  // [x, y]: z like x
  EXPECT_EQ(s.bodies[0].added_mass[5], 6.0);
  const Model sys = BuildModel(s);
  ASSERT_EQ(sys.free_bodies.size(), 1u);
  EXPECT_EQ(sys.points[2].kind, PointKind::kBody);
  EXPECT_NEAR(sys.bodies[0].initial_offset[5], 10 * M_PI / 180, 1e-15);
  // Turned 90 degrees about y (from +x towards -z): the local (2, -1, 0) is at (0, -1, -2).
  EXPECT_LT((sys.points[2].motion.rest() - Vec(70.0, -1.0, 8.0)).norm(), 1e-12);
}

TEST(SceneLoader, BodyErrors) {
  ExpectError(With("body = \"buoy\"", "body = \"boy\"", BodySystem()), "point[2].body",
              {"no body is named \"boy\""});
  // A point on a body moves with it: no motion of its own.
  ExpectError(With("body = \"buoy\"", "body = \"buoy\"\nmotion = \"free\"", BodySystem()),
              "point[2].motion", {"unknown key", "moves with it"});
  ExpectError(With("added_mass = [1.0, 2.0, 3.0, 4.0, 5.0, 6.0]", "added_mass = [1.0, 2.0]",
                   BodySystem()),
              "body[0].added_mass", {"six"});
  ExpectError(With("mass = 2.0e4", "mass = -1.0", BodySystem()), "body[0].mass", {"expected"});
  // A held body has no mass of its own to balance.
  ExpectError(With("motion = \"free\"\nposition = [70.0, 0.0, 10.0]", "position = [70.0, 0.0, 10.0]",
                   BodySystem()),
              "body[0].added_mass", {"unknown key", "motion = \"fixed\""});
}

TEST(SceneLoader, BodyBox) {
  // Drawn only, for any motion: its sizes and centre in the body's axes; none by default.
  const SceneDef none = ParseScene(BodySystem(), kFile);
  EXPECT_FALSE(none.bodies[0].has_box);
  const std::string boxed = With("mass = 2.0e4", "mass = 2.0e4\nbox = [4.0, 2.5, 3.0]\n"
                                 "box_center = [0.5, -1.0, 0.0]", BodySystem());
  const SceneDef s = ParseScene(boxed, kFile);
  ASSERT_TRUE(s.bodies[0].has_box);
  EXPECT_EQ(s.bodies[0].box[1], 2.5);
  EXPECT_EQ(s.bodies[0].box_center[1], -1.0);
  // No number of the model changes with it: the body's rest pose and loads are the same.
  const Model a = BuildModel(none), b = BuildModel(s);
  EXPECT_EQ(a.bodies[0].mass, b.bodies[0].mass);
  EXPECT_EQ((a.points[2].motion.rest() - b.points[2].motion.rest()).norm(), 0.0);
  // A held body takes it too.
  EXPECT_TRUE(ParseScene(With("motion = \"free\"\nposition = [70.0, 0.0, 10.0]",
                              "position = [70.0, 0.0, 10.0]\nbox = [1.0, 1.0, 1.0]",
                              With("mass = 2.0e4\nvolume = 30.0\ninertia = [1.0e5, 2.0e5]\n"
                                   "added_mass = [1.0, 2.0, 3.0, 4.0, 5.0, 6.0]\n"
                                   "initial_offset = [1.0, 0.0, 0.0, 0.0, 0.0, 10.0]\n",
                                   "", BodySystem())),
                         kFile)
                  .bodies[0]
                  .has_box);
}

TEST(SceneLoader, BodyBoxErrors) {
  auto box = [](const std::string& line) {
    return With("mass = 2.0e4", "mass = 2.0e4\n" + line, BodySystem());
  };
  // Negative, too large, two or four numbers, not numbers, not an array: refused, named.
  ExpectError(box("box = [4.0, -2.0, 3.0]"), "body[0].box", {"expected", "three", ">= 0", "-2"});
  ExpectError(box("box = [4.0, 2.0, 2e4]"), "body[0].box", {"expected", "up to 10000", "got 20000"});
  ExpectError(box("box = [4.0, 2.0]"), "body[0].box", {"expected an array of three"});
  ExpectError(box("box = [4.0, 2.0, 3.0, 1.0]"), "body[0].box", {"expected an array of three"});
  ExpectError(box("box = [4.0, \"x\", 3.0]"), "body[0].box", {"expected"});
  ExpectError(box("box = 4.0"), "body[0].box", {"expected an array of three"});
  ExpectError(box("box = [4.0, 2.0, 3.0]\nbox_center = [0.0, 1.0]"), "body[0].box_center",
              {"expected an array of three"});
  ExpectError(box("box = [4.0, 2.0, 3.0]\nbox_center = [0.0, true, 1.0]"), "body[0].box_center",
              {"expected"});
}

// A driven body that turns (issue 20): the fairlead on a ship whose trochoid turns it too.
const std::string kDrivenBody = R"([[body]]
name = "ship"
motion = "trochoid"
position = [70.0, 0.0, 10.0]
orientation = [0.0, 30.0, 0.0]
x_amplitudes = [1.0, 0.0]
rx_amplitudes = [2.0, 0.0]
ry_amplitudes = [0.0, 3.0]
period = 10.0
ramp_rate = 0.5

[[point]]
name = "fairlead"
body = "ship"
position = [2.0, -1.0, 0.5])";

std::string DrivenBodySystem(const std::string& from = "", const std::string& to = "") {
  const std::string text = SystemWith(
      "[[point]]\nname = \"fairlead\"\nposition = [70.0, 0.0, 10.0]", kDrivenBody);
  return from.empty() ? text : With(from, to, text);
}

TEST(SceneLoader, DrivenBodyTurnsByItsTrochoid) {
  const SceneDef s = ParseScene(DrivenBodySystem(), kFile);
  EXPECT_EQ(s.bodies[0].motion.rx_amplitudes[0], 2.0);
  EXPECT_EQ(s.bodies[0].motion.ry_amplitudes[1], 3.0);
  EXPECT_EQ(s.bodies[0].motion.rz_amplitudes[0], 0.0);
  const Model sys = BuildModel(s);
  ASSERT_TRUE(sys.bodies[0].turn.moves());
  const EndMotion& fairlead = sys.points[2].motion;
  ASSERT_TRUE(fairlead.turns());
  EXPECT_EQ(sys.points[2].kind, PointKind::kMoved);
  // Eq. (3) by hand for the reference point and the angles [deg], then r + R(theta) p.
  const double deg = M_PI / 180.0, w = 2 * M_PI / 10.0, nu = 0.5;
  for (double t : {0.0, 1.3, 7.9}) {
    const double ramp = 1 - (1 + nu * t) * std::exp(-nu * t);
    const Vec r(70.0 + ramp * std::cos(w * t), 0.0, 10.0);
    const Vec theta = Vec(2.0 * ramp * std::cos(w * t), 30.0 + 3.0 * ramp * std::sin(w * t), 0.0) * deg;
    Vec6 pose;
    pose << r, theta;
    // Round-off of 70 m: 1e-13.
    EXPECT_LT((fairlead.Position(t) - BodyPoint(pose, Vec(2.0, -1.0, 0.5))).norm(), 1e-13) << t;
  }
  // Without angle amplitudes nothing turns: the point's motion is the reference point's.
  const Model plain = BuildModel(ParseScene(
      DrivenBodySystem("rx_amplitudes = [2.0, 0.0]\nry_amplitudes = [0.0, 3.0]\n", ""), kFile));
  EXPECT_FALSE(plain.bodies[0].turn.moves());
  EXPECT_FALSE(plain.points[2].motion.turns());
}

TEST(SceneLoader, DrivenBodyTurnErrors) {
  ExpectError(DrivenBodySystem("rx_amplitudes = [2.0, 0.0]", "rx_amplitudes = [400.0, 0.0]"),
              "body[0].rx_amplitudes", {"expected", "in degrees", "360"});
  ExpectError(DrivenBodySystem("rx_amplitudes = [2.0, 0.0]", "rx_amplitudes = [2.0]"),
              "body[0].rx_amplitudes", {"expected an array of two"});
  // An end's or a point's motion does not turn: the keys are unknown there.
  ExpectError(SystemWith("position = [70.0, 0.0, 10.0]",
                         "position = [70.0, 0.0, 10.0]\nmotion = \"trochoid\"\nperiod = 10.0\n"
                         "ramp_rate = 0.5\nrz_amplitudes = [1.0, 0.0]"),
              "point[2].rz_amplitudes", {"unknown key"});
  // A fixed body has no motion keys.
  ExpectError(DrivenBodySystem("motion = \"trochoid\"", "motion = \"fixed\""), "body[0].",
              {"unknown key", "motion = \"fixed\" uses only the keys it needs"});
}

TEST(SceneLoader, WaveFollowingBodyTurnsThroughItsRaos) {
  const std::string waves = "\n[waves]\nheight = 2.0\nperiod = 8.0\ndepth = 60.0\n";
  const std::string wave_motion =
      "motion = \"wave\"\nposition = [70.0, 0.0, 10.0]\nry_rao = [1.5, 30.0]\nrz_rao = [0.5, 0.0]";
  const std::string troch =
      "motion = \"trochoid\"\nposition = [70.0, 0.0, 10.0]\norientation = [0.0, 30.0, 0.0]\n"
      "x_amplitudes = [1.0, 0.0]\nrx_amplitudes = [2.0, 0.0]\nry_amplitudes = [0.0, 3.0]\n"
      "period = 10.0\nramp_rate = 0.5";
  const SceneDef s = ParseScene(DrivenBodySystem(troch, wave_motion) + waves, kFile);
  const EndDef& m = s.bodies[0].motion;
  // A response r A cos(k x0 - omega t + p): [cos, sin] amplitudes r A (cos beta, sin beta),
  // beta = k x0 + p, A = 1 m; in degrees.
  const double k = WaveNumber(2 * M_PI / 8.0, 9.80665, 60.0);
  const double beta = k * 70.0 + 30.0 * M_PI / 180.0;
  EXPECT_NEAR(m.ry_amplitudes[0], 1.5 * std::cos(beta), 1e-12);
  EXPECT_NEAR(m.ry_amplitudes[1], 1.5 * std::sin(beta), 1e-12);
  EXPECT_NEAR(m.rz_amplitudes[0], 0.5 * std::cos(k * 70.0), 1e-12);
  EXPECT_EQ(m.rx_amplitudes[0], 0.0);
  EXPECT_TRUE(BuildModel(s).points[2].motion.turns());
  ExpectError(DrivenBodySystem(troch, "motion = \"wave\"\nposition = [70.0, 0.0, 10.0]\n"
                                      "rx_rao = [-1.0, 0.0]") + waves,
              "body[0].rx_rao", {"expected [amplitude ratio in deg/m from 0 to 1000", "got [-1, 0]"});
}

// A body's table of seven columns: its angles too.
TEST_F(TableMotion, BodyTableWithAngles) {
  WriteFile("turn.csv", "t,x,y,z,rx,ry,rz\n0,0,0,0,0,0,0\n2,0.5,0,0,1,-2,3\n4,0,0,0,0,5,0\n");
  const std::string troch =
      "motion = \"trochoid\"\nposition = [70.0, 0.0, 10.0]\norientation = [0.0, 30.0, 0.0]\n"
      "x_amplitudes = [1.0, 0.0]\nrx_amplitudes = [2.0, 0.0]\nry_amplitudes = [0.0, 3.0]\n"
      "period = 10.0\nramp_rate = 0.5";
  const std::string table = "motion = \"table\"\nposition = [70.0, 0.0, 10.0]\n"
                            "orientation = [0.0, 30.0, 0.0]\nfile = \"turn.csv\"";
  const SceneDef s = ParseScene(DrivenBodySystem(troch, table), scene_);
  ASSERT_EQ(s.bodies[0].motion.table.size(), 3u);
  EXPECT_EQ(s.bodies[0].motion.table[1][6], 3.0);
  EXPECT_EQ(s.bodies[0].motion.table[2][5], 5.0);
  const Model sys = BuildModel(s);
  // At a row the spline is the row: the pose (70.5, 0, 10), (1, 28, 3) degrees at t = 2.
  const double deg = M_PI / 180.0;
  Vec6 pose;
  pose << 70.5, 0.0, 10.0, 1.0 * deg, 28.0 * deg, 3.0 * deg;
  EXPECT_LT((sys.points[2].motion.Position(2.0) - BodyPoint(pose, Vec(2.0, -1.0, 0.5))).norm(),
            1e-12);
  // Headerless seven columns too; four columns turn nothing.
  WriteFile("bare.csv", "0,0,0,0,0,0,0\n1,0,0,0,0,1,0\n");
  EXPECT_TRUE(BuildModel(ParseScene(DrivenBodySystem(troch, With("turn.csv", "bare.csv", table)),
                                     scene_)).points[2].motion.turns());
  WriteFile("four.csv", "t,x,y,z\n0,0,0,0\n1,0.5,0,0\n");
  EXPECT_FALSE(BuildModel(ParseScene(DrivenBodySystem(troch, With("turn.csv", "four.csv", table)),
                                      scene_)).points[2].motion.turns());
  // The errors name the file, its line, the key and what was expected.
  WriteFile("short.csv", "t,x,y,z,rx,ry,rz\n0,0,0,0,0,0,0\n1,0,0,0,0,1\n");
  ExpectError(DrivenBodySystem(troch, With("turn.csv", "short.csv", table)), "body[0].file",
              {"short.csv:3", "expected seven numbers t,x,y,z,rx,ry,rz in s, m and degrees"},
              scene_);
  WriteFile("far.csv", "0,0,0,0,0,0,0\n1,0,0,0,0,400,0\n");
  ExpectError(DrivenBodySystem(troch, With("turn.csv", "far.csv", table)), "body[0].file",
              {"far.csv:2", "expected angles rx, ry, rz from -360 to 360 degrees"}, scene_);
  // check and run describe the turn, and warn of a run past a table still turning at its last
  // row: here linear, its first segment (1, -2, 3) degrees in 2 s, sqrt(14) / 2 = 1.871 deg/s,
  // its last (-1, 7, -3) degrees in 2 s, sqrt(59) / 2 = 3.841 deg/s.
  std::vector<std::string> notes, warnings;
  DescribeTables(ParseScene(DrivenBodySystem(troch, table + "\ninterpolation = \"linear\"") +
                                "\n[simulation]\nduration = 6.0\n",
                            scene_),
                 &notes, &warnings);
  ASSERT_EQ(notes.size(), 2u);
  EXPECT_NE(notes[1].find("body \"ship\": its table turns it too, at 1.871 deg/s at its first row "
                          "and 3.841 deg/s at its last"),
            std::string::npos)
      << notes[1];
  ASSERT_EQ(warnings.size(), 2u);  // its reference point still moves too (0.25 m/s)
  EXPECT_NE(warnings[1].find("past the table's last row at t = 4 s, where it still turns at "
                             "3.841 deg/s"),
            std::string::npos)
      << warnings[1];
  // An end's table does not turn.
  ExpectError(TableScene("turn.csv"), "ends.end.file",
              {"turn.csv:1", "seven columns t,x,y,z,rx,ry,rz turn a body"}, scene_);
  ExpectError(TableScene("bare.csv"), "ends.end.file",
              {"bare.csv:1", "seven columns t,x,y,z,rx,ry,rz turn a body"}, scene_);
}


// A MoorDyn file of one line and `points` points, all but its two ends attached to no line.
std::string ManyPointsMoorDyn(int points) {
  std::string text =
      "Many points no line uses\n"
      "---------------------- LINE TYPES -----------------------\n"
      "TypeName Diam Mass/m EA BA/-zeta EI Cd Ca CdAx CaAx\n"
      "(name) (m) (kg/m) (N) (N-s/-) (N-m^2) (-) (-) (-) (-)\n"
      "chain 0.1 100 1e9 -0.8 0 1.2 1 0 0\n"
      "---------------------- POINTS ---------------------------\n"
      "ID Attachment X Y Z Mass Volume CdA Ca\n"
      "(#) (-) (m) (m) (m) (kg) (m^3) (m^2) (-)\n"
      "1 Fixed 400 0 -100 0 0 0 0\n"
      "2 Fixed 0 0 -10 0 0 0 0\n";
  for (int i = 3; i <= points; ++i)
    text += std::to_string(i) + " Fixed " + std::to_string(i % 1000) + " " +
            std::to_string(i / 1000) + " -50 0 0 0 0\n";
  text +=
      "---------------------- LINES ----------------------------\n"
      "ID LineType AttachA AttachB UnstrLen NumSegs LineOutputs\n"
      "(#) (name) (#) (#) (m) (-) (-)\n"
      "1 chain 1 2 450 20 -\n"
      "---------------------- OPTIONS --------------------------\n"
      "100 WtrDpth\n";
  return text;
}

// A MoorDyn file of 60 000 points no line uses (1.8 MB) converts into a scene of more than
// 16 MiB, which the loader refuses as a scene file, while the MoorDyn file itself loaded (in
// 8 s: each name looked up among all the points before it). One limit for both forms: refused
// alike, naming the file, the size and the limit; at 45 000 points both load, the same points.
TEST_F(TableMotion, MoorDynFileAndItsSceneShareOneSizeLimit) {
  auto refusal = [](auto load) {
    try {
      load();
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string big = (dir_ / "big.txt").string();
  WriteFile("big.txt", ManyPointsMoorDyn(60000));
  const std::string converted = MoorDynToToml(ReadMoorDynFile(big), nullptr);
  ASSERT_GT(converted.size(), kMaxSceneBytes);
  char mib[32];  // 18.6 (its header lists a warning per point, each naming the file)
  std::snprintf(mib, sizeof mib, "%.1f", static_cast<double>(converted.size()) / (1 << 20));
  WriteFile("big.toml", converted);
  const std::string too_large = refusal([&] { LoadScene((dir_ / "big.toml").string()); });
  EXPECT_NE(too_large.find("big.toml: larger than 16 MiB"), std::string::npos) << too_large;
  const std::string message = refusal([&] { LoadScene(big); });
  EXPECT_EQ(message, big + ": the scene it converts into (cablefilm convert) is " + mib +
                         " MiB, from 60000 rows of POINTS, 1 of LINES and 1 of LINE TYPES; "
                         "expected at most 16 MiB, the size limit of a scene file (fewer points "
                         "or lines)");
  EXPECT_EQ(refusal([&] { MoorDynSceneText(big, nullptr); }), message);

  const std::string fits = (dir_ / "fits.txt").string();
  WriteFile("fits.txt", ManyPointsMoorDyn(45000));
  std::vector<std::string> warnings;
  const std::string text = MoorDynSceneText(fits, &warnings);
  EXPECT_LT(text.size(), kMaxSceneBytes);
  EXPECT_EQ(warnings.size(), 44998u);  // a point no line uses: each a warning
  WriteFile("fits.toml", text);
  const SceneDef as_moordyn = LoadScene(fits), as_scene = LoadScene((dir_ / "fits.toml").string());
  ASSERT_EQ(as_moordyn.points.size(), 45000u);
  ASSERT_EQ(as_scene.points.size(), 45000u);
  EXPECT_EQ(as_scene.points[44999].name, "45000");
  EXPECT_EQ(as_scene.points[44999].motion.position, as_moordyn.points[44999].motion.position);
  EXPECT_EQ(as_moordyn.warnings.size(), 44998u);
}

}  // namespace
}  // namespace cablefilm
