// Every validation rule of shared/scene-format.md: each bad input is fed through ParseScene and
// the error must name the file, the key and what was expected. Good scenes load, with defaults.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/equilibrium.h"
#include "core/error.h"
#include "scene/build_model.h"
#include "scene/scene_loader.h"

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
  EXPECT_EQ(s.sections.size(), 2u);
  EXPECT_EQ(s.weights.size(), 1u);
  EXPECT_EQ(s.name, "bad_scene");
  EXPECT_EQ(BuildModel(s).weight_stations, std::vector<int>{18});
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
  EXPECT_NO_THROW(SolveEquilibrium(BuildModel(s)));
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

TEST_F(TableMotion, GoodTableLoads) {
  WriteFile("ship.csv", "t,x,y\n0,0,0\n1,0.5,0.1\n2,0.2,-0.3\n");
  const SceneDef s = ParseScene(TableScene("ship.csv"), scene_);
  ASSERT_EQ(s.end.table.size(), 3u);
  EXPECT_DOUBLE_EQ(s.end.table[2][2], -0.3);
  const CableModel m = BuildModel(s);
  EXPECT_NEAR(m.end.Position(1.0).x(), 80.5, 1e-12);  // offsets from the rest position
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
  EXPECT_TRUE(s.weights.empty());
  EXPECT_EQ(s.initial, InitialStateKind::kEquilibrium);
  EXPECT_EQ(s.simulation.time_step, 0.0);  // "auto"
  EXPECT_EQ(s.model, CableModelKind::kElastic);
  EXPECT_EQ(s.start.motion, EndMotionKind::kFixed);
  EXPECT_EQ(s.end.motion, EndMotionKind::kFixed);
  EXPECT_EQ(s.materials[0].drag_coefficient, 1.2);
  EXPECT_EQ(s.materials[0].added_mass_coefficient, 1.0);
  EXPECT_GT(s.output.interval, 0.0);
}

TEST(SceneLoader, ShippedScenesLoadBuildAndSolve) {
  for (const char* name : {"polachek1963", "catenary", "taut_string", "hanging_chain"}) {
    const std::string path = std::string(CABLEFILM_SOURCE_DIR) + "/scenes/" + name + ".toml";
    SceneDef s;
    ASSERT_NO_THROW(s = LoadScene(path)) << path;
    const CableModel m = BuildModel(s);
    EquilibriumReport rep;
    EXPECT_NO_THROW(SolveEquilibrium(m, &rep)) << path;
    EXPECT_LE(rep.residual, 1e-6 * rep.force_scale) << path;
  }
  try {
    LoadScene("/nonexistent/dir/scene.toml");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/dir/scene.toml"), std::string::npos);
  }
}

}  // namespace
}  // namespace cablefilm
