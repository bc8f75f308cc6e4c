// Issue 20, MoorDyn's input files: the scene a MoorDyn file converts to, read back with toml++
// and held against the mapping of docs/moordyn.md (the axes, E = EA / area, the seabed), and
// the three shipped scenes written as MoorDyn files (tests/scenes/moordyn/) converted back to
// their own materials and geometry.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <toml++/toml.h>
#include <vector>

#include "core/body.h"
#include "core/error.h"
#include "core/forces.h"
#include "core/inputs.h"
#include "core/step.h"
#include "core/equilibrium.h"
#include "core/relaxation.h"
#include "scene/moordyn_axes.h"
#include "scene/build_model.h"
#include "scene/moordyn_convert.h"
#include "scene/scene_parser.h"
#include "scene/toml_text.h"

namespace cablefilm {
namespace {

// The statics as a run finds them: Newton, and where it fails the relaxation's motion.
std::vector<State> SolveRelaxing(const Model& sys, const StepOptions& step,
                                 EquilibriumReport* report) {
  EquilibriumOptions options;
  options.relaxation = step;
  options.inputs = SceneInputs(sys.lines[0]);
  return SolveEquilibrium(sys, report, options);
}

}  // namespace
namespace {

const std::string kSource = CABLEFILM_SOURCE_DIR;
const std::string kDir = kSource + "/tests/scenes/moordyn/";

// Relative tolerance of a value computed from the file's numbers (one or two roundings of a
// product or quotient, then the shortest decimal that reads back the same: a few 1e-16).
constexpr double kRel = 1e-14;

double Num(const toml::node_view<const toml::node>& n) {
  EXPECT_TRUE(n.is_number()) << n;
  return n.value<double>().value_or(std::nan(""));
}

std::array<double, 3> Vec(const toml::node_view<const toml::node>& n) {
  const toml::array* a = n.as_array();
  EXPECT_TRUE(a && (a->size() == 2 || a->size() == 3)) << n;
  if (!a) return {};
  std::array<double, 3> v{};
  for (std::size_t i = 0; i < a->size(); ++i) v[i] = a->get(i)->value<double>().value();
  return v;
}

void ExpectNear(const std::array<double, 3>& a, const std::array<double, 3>& b, double tol) {
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(a[i], b[i], tol) << "component " << i;
}

// The [[name]] table whose name is `key`.
toml::node_view<const toml::node> Named(const toml::table& t, const char* array,
                                        const std::string& key) {
  const toml::array* a = t[array].as_array();
  if (a)
    for (const toml::node& n : *a)
      if (n.as_table() && (*n.as_table())["name"].value<std::string>() == key)
        return toml::node_view<const toml::node>(n);
  ADD_FAILURE() << "no [[" << array << "]] named " << key;
  return {};
}

struct Converted {
  toml::table scene;
  std::vector<std::string> warnings;
  std::string text;
};

Converted Convert(const MoorDynSystem& system) {
  Converted c;
  c.text = MoorDynToToml(system, &c.warnings);
  try {
    c.scene = toml::parse(c.text, std::string("converted.toml"));
  } catch (const toml::parse_error& e) {
    ADD_FAILURE() << "not TOML: " << e << "\n" << c.text;
  }
  return c;
}

bool HasWarning(const std::vector<std::string>& warnings, const std::string& part) {
  for (const auto& w : warnings)
    if (w.find(part) != std::string::npos) return true;
  return false;
}

TEST(MoorDynConvert, ThreeLegSpreadFollowsTheMapping) {
  const Converted c = Convert(ReadMoorDynFile(kDir + "three_leg_spread.txt"));
  const toml::table& s = c.scene;
  EXPECT_EQ(s["title"].value<std::string>(),
            "Three-leg spread mooring in 150 m of water, a clump weight on leg 3 (cablefilm's "
            "reader test)");
  EXPECT_EQ(Num(s["environment"]["gravity"]), 9.81);  // MoorDyn's documented default
  EXPECT_EQ(Num(s["environment"]["fluid_density"]), 1025.0);
  // The seabed: y = -WtrDpth; stiffness and damping per metre of line: kBot d, cBot d with the
  // longest line's d (the chain's, 0.137 m); the wire's other diameter is a warning.
  EXPECT_EQ(Num(s["seabed"]["y"]), -150.0);
  EXPECT_NEAR(Num(s["seabed"]["stiffness"]), 3.0e6 * 0.137, kRel * 4.11e5);
  EXPECT_NEAR(Num(s["seabed"]["damping"]), 3.0e5 * 0.137, kRel * 4.11e4);
  EXPECT_EQ(Num(s["seabed"]["friction"]), 0.5);
  EXPECT_TRUE(HasWarning(c.warnings, "\"wire\" (d 0.076 m)"));

  // Materials: area = pi d^2 / 4 (MoorDyn's d is volume-equivalent), E = EA / area,
  // BA >= 0 -> axial_damping = BA / area, BA < 0 -> moordyn_axial_damping_ratio = -BA.
  const auto chain = Named(s, "material", "chain");
  const double chain_area = M_PI * 0.137 * 0.137 / 4;
  EXPECT_EQ(Num(chain["diameter"]), 0.137);
  EXPECT_NEAR(Num(chain["area"]), chain_area, kRel * chain_area);
  EXPECT_EQ(Num(chain["mass_per_length"]), 115.0);
  EXPECT_NEAR(Num(chain["youngs_modulus"]) * Num(chain["area"]), 5.4e8, kRel * 5.4e8);
  EXPECT_EQ(Num(chain["drag_coefficient"]), 2.4);
  EXPECT_EQ(Num(chain["added_mass_coefficient"]), 1.0);
  EXPECT_EQ(Num(chain["moordyn_axial_damping_ratio"]), 0.8);
  EXPECT_FALSE(chain["axial_damping"]);
  EXPECT_FALSE(chain["axial_damping_ratio"]);
  const auto wire = Named(s, "material", "wire");
  const double wire_area = M_PI * 0.076 * 0.076 / 4;
  EXPECT_NEAR(Num(wire["youngs_modulus"]), 5.6e8 / wire_area, kRel * 5.6e8 / wire_area);
  EXPECT_NEAR(Num(wire["axial_damping"]), 1.0e5 / wire_area, kRel * 1.0e5 / wire_area);
  // CdAx, CaAx -> the tangential drag and added mass coefficients as they are (both on the
  // same d and pi d^2 / 4 as MoorDyn's), without a warning; 0 writes no key (the default).
  EXPECT_EQ(Num(chain["tangential_drag_coefficient"]), 0.4);
  EXPECT_EQ(Num(chain["tangential_added_mass_coefficient"]), 0.5);
  EXPECT_FALSE(wire["tangential_drag_coefficient"]);
  EXPECT_FALSE(wire["tangential_added_mass_coefficient"]);
  EXPECT_FALSE(HasWarning(c.warnings, "CdAx"));
  EXPECT_FALSE(HasWarning(c.warnings, "CaAx"));

  // Points: MoorDyn (x, y, z) -> cablefilm (x, z, -y).
  const auto anchor2 = Named(s, "point", "2");
  EXPECT_EQ(anchor2["motion"].value<std::string>(), "fixed");
  ExpectNear(Vec(anchor2["position"]), {-400.0, -150.0, -692.8203}, 0);
  const auto fairlead5 = Named(s, "point", "5");  // "Vessel": held where it is written
  EXPECT_EQ(fairlead5["motion"].value<std::string>(), "fixed");
  ExpectNear(Vec(fairlead5["position"]), {-10.0, -10.0, -17.3205}, 0);
  const auto clump = Named(s, "point", "7");
  EXPECT_EQ(clump["motion"].value<std::string>(), "free");
  ExpectNear(Vec(clump["position"]), {-220.0, -140.0, 381.0512}, 0);
  EXPECT_EQ(Num(clump["mass"]), 5000.0);
  EXPECT_EQ(Num(clump["volume"]), 0.5);
  ExpectNear(Vec(clump["added_volume"]), {0.5, 0.5, 0.5}, 0);        // Ca V
  ExpectNear(Vec(clump["drag_coefficient"]), {1.0, 1.0, 1.0}, 0);
  ExpectNear(Vec(clump["drag_area"]), {2.0, 2.0, 2.0}, 0);           // CdA
  EXPECT_FALSE(Named(s, "point", "1")["mass"]);  // a fixed point has none

  // Lines: start = AttachA, end = AttachB, one section.
  const auto leg3 = Named(s, "line", "4");
  EXPECT_EQ(leg3["model"].value<std::string>(), "elastic");
  EXPECT_EQ(leg3["start"].value<std::string>(), "7");
  EXPECT_EQ(leg3["end"].value<std::string>(), "6");
  const toml::array* sections = leg3["section"].as_array();
  ASSERT_TRUE(sections && sections->size() == 1);
  const auto section = toml::node_view<const toml::node>(*sections->get(0));
  EXPECT_EQ(section["material"].value<std::string>(), "wire");
  EXPECT_EQ(Num(section["length"]), 450.0);
  EXPECT_EQ(section["segments"].value<int64_t>(), 30);
  EXPECT_EQ(s["line"].as_array()->size(), 4u);
  EXPECT_EQ(s["point"].as_array()->size(), 7u);

  // The options cablefilm does not map: dtM and TmaxIC as comments, writeLog a warning.
  EXPECT_NE(c.text.find("# OPTIONS dtM = 0.001 s (line 29): MoorDyn's time step, a hint"),
            std::string::npos);
  EXPECT_NE(c.text.find("# OPTIONS TmaxIC = 60 (line 35): MoorDyn's initial-condition"),
            std::string::npos);
  EXPECT_TRUE(HasWarning(c.warnings, "three_leg_spread.txt:37: OPTIONS writeLog = 1: ignored"));
}

// Each key written from a row or an option knows the file's line, row and column it came from,
// for messages about the scene (key_source.h); MoorDyn's defaults came from no row.
TEST(MoorDynConvert, KeysKnowTheRowAndColumnTheyCameFrom) {
  KeySources sources;
  MoorDynToToml(ReadMoorDynFile(kDir + "three_leg_spread.txt"), nullptr, &sources);
  auto place = [&](const std::string& key) {
    const auto it = sources.find(key);
    return it == sources.end() ? std::string("(none)")
                               : std::to_string(it->second.line) + ": " + it->second.place;
  };
  EXPECT_EQ(place("material[1]"), "9: LINE TYPES row 2");
  EXPECT_EQ(place("material[1].youngs_modulus"), "9: LINE TYPES row 2, column EA");
  EXPECT_EQ(place("material[1].axial_damping"), "9: LINE TYPES row 2, column BA/-zeta");
  EXPECT_EQ(place("material[0].moordyn_axial_damping_ratio"),
            "8: LINE TYPES row 1, column BA/-zeta");
  EXPECT_EQ(place("material[0].area"), "8: LINE TYPES row 1, column Diam");
  EXPECT_EQ(place("point[4].motion"), "17: POINTS row 5, column Attachment");
  EXPECT_EQ(place("point[6].position"), "20: POINTS row 7, columns X, Y, Z");
  EXPECT_EQ(place("point[6].added_volume"), "20: POINTS row 7, columns Ca, Volume");
  EXPECT_EQ(place("line[3]"), "27: LINES row 4");
  EXPECT_EQ(place("line[3].start"), "27: LINES row 4, column AttachA");
  EXPECT_EQ(place("line[3].section[0].length"), "27: LINES row 4, column UnstrLen");
  EXPECT_EQ(place("environment.fluid_density"), "32: OPTIONS WtrDnsty");
  EXPECT_EQ(place("seabed.y"), "33: OPTIONS WtrDpth");
  EXPECT_EQ(place("seabed.stiffness"), "30: OPTIONS kBot");
  EXPECT_EQ(place("seabed.friction"), "34: OPTIONS FrictionCoefficient");
  EXPECT_EQ(place("environment.gravity"), "(none)");  // MoorDyn's default
  EXPECT_EQ(place("waves.height"), "(none)");         // its still surface: from no row
  EXPECT_EQ(place("line[3].model"), "(none)");
}

// A body's points: X0 + Rx(r0) Ry(p0) Rz(y0) p, then MoorDyn's axes to cablefilm's.
TEST(MoorDynConvert, BodyPointsAreFixedAtTheBodysPose) {
  MoorDynBody body;
  body.position = {10, 20, -5};
  body.rotation = {0, 0, 90};  // yaw: the bow (+x) turns to port (+y)
  ExpectNear(MoorDynBodyPoint(body, {1, 0, 0}), {10, 21, -5}, 1e-15);
  body.rotation = {0, 90, 0};  // pitch: the bow goes down
  ExpectNear(MoorDynBodyPoint(body, {1, 0, 0}), {10, 20, -6}, 1e-15);
  body.rotation = {90, 0, 0};  // roll: the starboard side (-y) goes down
  ExpectNear(MoorDynBodyPoint(body, {0, -1, 0}), {10, 20, -6}, 1e-15);
  // Rx Ry Rz, the yaw applied first: (1,0,0) -yaw-> (0,1,0) -roll-> (0,0,1). (Rz Rx would
  // give (0,1,0).)
  body.rotation = {90, 0, 90};
  ExpectNear(MoorDynBodyPoint(body, {1, 0, 0}), {10, 20, -4}, 1e-15);
  body.rotation = {30, 0, 0};
  ExpectNear(MoorDynBodyPoint(body, {0, 2, 0}), {10, 20 + 2 * std::cos(M_PI / 6),
                                                 -5 + 2 * std::sin(M_PI / 6)}, 1e-14);
  ExpectNear(MoorDynToCablefilm({1, 2, 3}), {1, 3, -2}, 0);

  MoorDynSystem system;
  system.file = "sys.txt";
  system.line_types.push_back({5, "chain", 0.1, 150, 1e8, -1, 0, 2.3, 1, 0, 0, 0});
  body.rotation = {0, 0, 90};
  body.attachment = MoorDynAttachment::kFixed;
  body.line = 9;
  body.id = 1;
  system.bodies.push_back(body);
  MoorDynPoint anchor;
  anchor.id = 1;
  anchor.position = {-500, 0, -150};
  MoorDynPoint fairlead;
  fairlead.id = 2;
  fairlead.attachment = MoorDynAttachment::kBody;
  fairlead.body = 1;
  fairlead.position = {1, 0, 0};
  system.points = {anchor, fairlead};
  system.lines.push_back({14, 1, "chain", 1, 2, 550, 20});
  const Converted c = Convert(system);
  const auto p = Named(c.scene, "point", "2");
  EXPECT_EQ(p["body"].value<std::string>(), "1");  // on the body, in its axes
  ExpectNear(Vec(p["position"]), {1, 0, 0}, 0);
  const auto held = Named(c.scene, "body", "1");
  EXPECT_EQ(held["motion"].value<std::string>(), "fixed");
  ExpectNear(Vec(held["orientation"]), {0, 90, 0}, 0);  // a yaw: about cablefilm's y
  // Where the body puts it: MoorDyn (10, 21, -5) is cablefilm's (10, -5, -21).
  const SceneDef scene = ParseScene(c.text, "sys.toml");
  EXPECT_LT((BuildModel(scene).points[1].motion.rest() - Eigen::Vector3d(10, -5, -21)).norm(),
            1e-14);
  // No WtrDpth: MoorDyn's default 0, lowered to the deepest point (the anchor), as MoorDyn.
  EXPECT_EQ(Num(c.scene["seabed"]["y"]), -150.0);

  // A free body: its mass, inertia and centre of gravity in cablefilm's axes.
  system.bodies[0].attachment = MoorDynAttachment::kFree;
  system.bodies[0].mass = 1000;
  system.bodies[0].cg = {0, 0.5, -2};
  system.bodies[0].inertia = {10, 20, 30};
  system.bodies[0].volume = 2;
  system.bodies[0].ca = {1, 0.5, 0.25};
  const Converted f = Convert(system);
  const auto free = Named(f.scene, "body", "1");
  EXPECT_EQ(free["motion"].value<std::string>(), "free");
  ExpectNear(Vec(free["center_of_gravity"]), {0, -2, -0.5}, 0);
  ExpectNear(Vec(free["inertia"]), {10, 30, 20}, 0);
  EXPECT_EQ(Num(free["added_mass"][1]), 1025.0 * 0.25 * 2);  // MoorDyn's z: cablefilm's y
  EXPECT_EQ(BuildModel(ParseScene(f.text, "sys.toml")).free_bodies.size(), 1u);
}

// A MoorDyn body's angles as cablefilm's: the same turn, whatever the angles. A body point at
// MoorDyn's X0 + Rx(r0) Ry(p0) Rz(y0) p is, in cablefilm's axes, at r + R(theta) p' with the
// converted angles and p' the point in cablefilm's axes.
TEST(MoorDynConvert, BodyAnglesAreTheSameTurn) {
  const MoorDynVec local = {3, -2, 1.5};
  for (const MoorDynVec& rpy : std::vector<MoorDynVec>{
           {0, 0, 37}, {10, 0, 0}, {0, -25, 0}, {12, -7, 140}, {-80, 33, -170}, {5, 60, 5}}) {
    MoorDynBody body;
    body.position = {4, -6, -8};
    body.rotation = rpy;
    const MoorDynVec want = MoorDynToCablefilm(MoorDynBodyPoint(body, local));
    const MoorDynVec angles = MoorDynAnglesToCablefilm(rpy);
    Vec6 pose;
    const MoorDynVec r = MoorDynToCablefilm(body.position);
    pose << r[0], r[1], r[2], angles[0] * M_PI / 180, angles[1] * M_PI / 180,
        angles[2] * M_PI / 180;
    const MoorDynVec p = MoorDynToCablefilm(local);
    const Eigen::Vector3d got = BodyPoint(pose, Eigen::Vector3d(p[0], p[1], p[2]));
    EXPECT_LT((got - Eigen::Vector3d(want[0], want[1], want[2])).norm(), 1e-12)
        << rpy[0] << " " << rpy[1] << " " << rpy[2];
  }
}

TEST(MoorDynConvert, NamesAndTitlesAreEscaped) {
  EXPECT_EQ(TomlString("a \"b\" \\ c"), "\"a \\\"b\\\" \\\\ c\"");
  EXPECT_EQ(TomlString("tab\tnl\n\x7f"), "\"tab\\u0009nl\\u000A\\u007F\"");
  EXPECT_EQ(TomlString("\xff" "x"), "\"\xEF\xBF\xBDx\"");  // not UTF-8 -> U+FFFD
  EXPECT_EQ(TomlNumber(850), "850.0");
  EXPECT_EQ(TomlNumber(-0.0), "0.0");
  EXPECT_EQ(TomlNumber(0.1), "0.1");
  EXPECT_EQ(TomlNumber(3e5), "300000.0");
  EXPECT_EQ(TomlNumber(1e-7), "1e-07");
  EXPECT_EQ(TomlNumber(2.5e20), "2.5e+20");
  EXPECT_EQ(std::stod(TomlNumber(M_PI)), M_PI);

  MoorDynSystem system = ReadMoorDynFile(kDir + "catenary.txt");
  const std::string odd = "ch\"ain\\" "\x01" "\xfe";
  system.line_types[0].name = odd;
  system.lines[0].type = odd;
  system.title = std::string(300, 'T') + " \"quoted\"";
  const Converted c = Convert(system);
  const std::string material = c.scene["material"][0]["name"].value<std::string>().value_or("");
  EXPECT_EQ(material, "ch\"ain\\\x01\xEF\xBF\xBD");
  EXPECT_EQ(c.scene["line"][0]["section"][0]["material"].value<std::string>(), material);
  EXPECT_EQ(c.scene["title"].value<std::string>(), std::string(200, 'T'));  // at most 200
}

// TmaxIC = 0: MoorDyn makes no initial-condition solve and starts from the file's positions:
// initial.state = "straight", traced to the option's line; any other TmaxIC leaves the statics.
TEST(MoorDynConvert, NoInitialConditionSolveStartsAsGiven) {
  const std::string path = kDir + "pendulum.txt";
  const Converted given = Convert(ReadMoorDynFile(path));
  EXPECT_EQ(given.scene["initial"]["state"].value<std::string>(), "straight");
  KeySources sources;
  MoorDynToToml(ReadMoorDynFile(path), nullptr, &sources);
  ASSERT_TRUE(sources.count("initial.state"));
  EXPECT_EQ(sources.at("initial.state").line, 18);
  EXPECT_EQ(sources.at("initial.state").place, "OPTIONS TmaxIC");
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  std::string solving = text.str();
  solving.replace(solving.find("0.0 TmaxIC"), 10, "10000 TmaxIC");
  EXPECT_FALSE(Convert(ReadMoorDynText(solving, "pendulum.txt")).scene["initial"]);
}

// The options: a seabed above a point is lowered to it (as MoorDyn), with a warning; kBot 0 is
// no seabed; waves, currents and unknown options are warnings, and the defaults are written.
TEST(MoorDynConvert, OptionsAndTheirDefaults) {
  const std::string text = R"(Options
---------------------- LINE TYPES -----------------------
TypeName Diam Mass/m EA BA/-zeta EI Cd Ca CdAx CaAx
(name) (m) (kg/m) (N) (N-s/-) (N-m^2) (-) (-) (-) (-)
chain 0.1 150.0 1e8 0 1e4 2.3 1 0 0
---------------------- POINTS ---------------------------
ID Attachment X Y Z Mass Volume CdA Ca
(#) (-) (m) (m) (m) (kg) (m^3) (m^2) (-)
1 Fixed -500 0 -160 0 0 0 0
2 Coupled 0 0 -9 0 0 0 0
---------------------- LINES ----------------------------
ID LineType AttachA AttachB UnstrLen NumSegs LineOutputs
(#) (name) (#) (#) (m) (-) (-)
1 chain 1 2 550 20 -
---------------------- OPTIONS --------------------------
150 WtrDpth
1 WaveKin
0 Currents
euler tScheme
)";
  const Converted c = Convert(ReadMoorDynText(text, "sys.txt"));
  EXPECT_EQ(Num(c.scene["seabed"]["y"]), -160.0);
  EXPECT_TRUE(HasWarning(c.warnings, "sys.txt:9: point 1 lies below the seabed of WtrDpth 150 m"));
  EXPECT_TRUE(HasWarning(c.warnings, "sys.txt:17: OPTIONS WaveKin = 1: waves are not imported "
                                     "(MoorDyn takes them from its files or its calling program)"));
  // MoorDyn's still water surface at z = 0, the depth that of the seabed.
  EXPECT_EQ(Num(c.scene["waves"]["height"]), 0.0);
  EXPECT_FALSE(c.scene["waves"]["depth"]);
  EXPECT_FALSE(c.scene["waves"]["surface_y"]);  // 0, the default
  // Externally driven waves (WaveKin 1) are the calling program's as given, stretched by
  // nothing; MoorDyn's own (WaveKin 2, 3, 7) are stretched to the instantaneous surface, as
  // Wheeler's; none (WaveKin 0 or not given) alike.
  EXPECT_EQ(c.scene["waves"]["kinematics"].value<std::string>(), "linear");
  for (const char* own : {"7 WaveKin", "3 WaveKin", "0 WaveKin", "0 Currents"}) {
    std::string other = text;
    other.replace(other.find("1 WaveKin"), 9, own);
    EXPECT_EQ(Convert(ReadMoorDynText(other, "sys.txt")).scene["waves"]["kinematics"]
                  .value<std::string>(),
              "wheeler")
        << own;
  }
  EXPECT_FALSE(HasWarning(c.warnings, "Currents"));
  EXPECT_TRUE(HasWarning(c.warnings, "sys.txt:19: OPTIONS tScheme = euler: ignored"));
  EXPECT_TRUE(HasWarning(c.warnings, "sys.txt:5: LINE TYPES \"chain\": EI 10000 N m^2: bending "
                                     "stiffness ignored"));
  EXPECT_EQ(Num(c.scene["environment"]["gravity"]), 9.81);
  EXPECT_EQ(Num(c.scene["environment"]["fluid_density"]), 1025.0);
  EXPECT_NEAR(Num(c.scene["seabed"]["stiffness"]), 3e6 * 0.1, kRel * 3e5);  // kBot's default
  EXPECT_NEAR(Num(c.scene["seabed"]["damping"]), 3e5 * 0.1, kRel * 3e4);    // cBot's
  EXPECT_EQ(Num(c.scene["seabed"]["friction"]), 0.0);
  EXPECT_EQ(Num(Named(c.scene, "material", "chain")["axial_damping"]), 0.0);  // BA 0
  // The warnings head the scene too, as comments.
  EXPECT_NE(c.text.find("#   sys.txt:19: OPTIONS tScheme = euler: ignored\n"), std::string::npos);

  const Converted flat = Convert(ReadMoorDynText(text + "0 kBot\n", "sys.txt"));
  EXPECT_FALSE(flat.scene["seabed"]);
  EXPECT_EQ(Num(flat.scene["waves"]["depth"]), 160.0);  // no seabed: the deepest point's
  EXPECT_TRUE(HasWarning(flat.warnings, "sys.txt:20: kBot 0: MoorDyn's seabed has no stiffness"));
}

// --- The shipped scenes that a MoorDyn file can express, as MoorDyn files ---------------

// What a shipped scene's end becomes: its position in 3D, and "free" or "fixed" (a driven end,
// trochoid or table, is a Coupled point, which stays where it is written).
struct End {
  std::array<double, 3> position;
  std::string motion;
};
End SceneEnd(const toml::table& scene, const char* which) {
  const auto end = scene["ends"][which];
  const std::string motion = end["motion"].value_or(std::string("fixed"));
  return {Vec(end["position"]), motion == "free" ? "free" : "fixed"};
}

void ExpectSameScene(const std::string& moordyn, const std::string& shipped) {
  SCOPED_TRACE(moordyn);
  const toml::table scene = toml::parse_file(kSource + "/scenes/" + shipped);
  const Converted c = Convert(ReadMoorDynFile(kDir + moordyn));
  const toml::table& s = c.scene;
  EXPECT_EQ(Num(s["environment"]["gravity"]), Num(scene["environment"]["gravity"]));
  EXPECT_EQ(Num(s["environment"]["fluid_density"]), Num(scene["environment"]["fluid_density"]));

  // The material: the same d, mass per length, EA, drag and added mass coefficients (the
  // scene's defaults 1.2 and 1.0 when it leaves them out). The area is pi d^2 / 4, not the
  // scene's: both scenes are in vacuum, where the area enters only through EA = E area.
  const auto m = s["material"][0];
  const auto sm = scene["material"][0];
  EXPECT_EQ(m["name"].value<std::string>(), sm["name"].value<std::string>());
  EXPECT_EQ(Num(m["diameter"]), Num(sm["diameter"]));
  EXPECT_EQ(Num(m["mass_per_length"]), Num(sm["mass_per_length"]));
  const double ea = Num(sm["youngs_modulus"]) * Num(sm["area"]);
  EXPECT_NEAR(Num(m["youngs_modulus"]) * Num(m["area"]), ea, kRel * ea);
  EXPECT_EQ(Num(m["drag_coefficient"]), sm["drag_coefficient"].value_or(1.2));
  EXPECT_EQ(Num(m["added_mass_coefficient"]), sm["added_mass_coefficient"].value_or(1.0));
  EXPECT_EQ(Num(scene["environment"]["fluid_density"]), 0.0);

  // The geometry: one line from the start's point to the end's, of the same length and links.
  ASSERT_EQ(s["line"].as_array()->size(), 1u);
  const auto line = s["line"][0];
  EXPECT_EQ(Num(line["section"][0]["length"]), Num(scene["cable"]["section"][0]["length"]));
  EXPECT_EQ(line["section"][0]["segments"].value<int64_t>(),
            scene["cable"]["section"][0]["segments"].value<int64_t>());
  for (const char* which : {"start", "end"}) {
    const auto point = Named(s, "point", line[which].value<std::string>().value_or(""));
    const End end = SceneEnd(scene, which);
    EXPECT_EQ(point["motion"].value<std::string>(), end.motion) << which;
    ExpectNear(Vec(point["position"]), end.position, 0);
    EXPECT_FALSE(point["mass"]) << which;  // a free end is a station with no weight
  }
  // MoorDyn's seabed, which the scenes do not have, lies far below the line; in vacuum no
  // water surface.
  EXPECT_LE(Num(s["seabed"]["y"]), -100.0);
  EXPECT_FALSE(s["waves"]);
}

// MoorDyn's lines have no buoyancy above the still water level (the submerged fraction of each
// segment): a buoyant line anchored D = 10 m down and 20 m long floats with half its length at
// the surface. Hydrostatics: the anchor holds the net buoyancy of the submerged length alone,
// (rho pi d^2 / 4 - m) g D = (1025 x 0.070686 - 20) 9.81 x 10 = 5145 N, give or take the
// stations at the surface (a link of 0.5 m either way: 5 %); without the surface the whole line
// would pull, twice that.
TEST(MoorDynConvert, LinesFloatAtTheStillWaterSurface) {
  const std::string text = R"(A buoyant line
---------------------- LINE TYPES -----------------------
TypeName Diam Mass/m EA BA/-zeta EI Cd Ca CdAx CaAx
(name) (m) (kg/m) (N) (N-s/-) (N-m^2) (-) (-) (-) (-)
float 0.3 20.0 1e7 -0.5 0 1.2 1 0 0
---------------------- POINTS ---------------------------
ID Attachment X Y Z Mass Volume CdA Ca
(#) (-) (m) (m) (m) (kg) (m^3) (m^2) (-)
1 Fixed 0 0 -10 0 0 0 0
2 Free 3 0 0 0 0 0 0
---------------------- LINES ----------------------------
ID LineType AttachA AttachB UnstrLen NumSegs LineOutputs
(#) (name) (#) (#) (m) (-) (-)
1 float 1 2 20 40 -
---------------------- OPTIONS --------------------------
10 WtrDpth
)";
  const Converted c = Convert(ReadMoorDynText(text, "float.txt"));
  const Model sys = BuildModel(ParseScene(c.text, "float.toml"));
  const std::vector<State> states = SolveEquilibrium(sys);
  ASSERT_EQ(states.size(), 1u);
  const LineModel& m = sys.lines[0];
  Eigen::VectorXd tension(m.line.links);
  LinkGeometry g;
  g.length.resize(m.line.links);
  g.tangent.resize(kDim, m.line.links);
  ComputeGeometry(states[0].x, g);
  ComputeHookeTensions(m, g, tension);
  const double net = (1025.0 * M_PI * 0.3 * 0.3 / 4 - 20.0) * 9.81 * 10.0;  // [N]
  EXPECT_NEAR(tension[0], net, 0.05 * net);
  // Nothing rises above the surface by more than the line's diameter.
  EXPECT_LE(states[0].x.row(kVertical).maxCoeff(), 0.3);
}

// A free body given above the anchor it hangs below (MoorDyn runs such a file from where it
// puts things, TmaxIC = 0): Newton from there cannot balance it (its one link passes through
// the anchor on the way); the system's damped motion brings it near enough
// (core/relaxation.h). Hand values: the body weighs (20 - 1025 x 0.004) 9.81 = 155.9 N in
// water, the line (4 m of 8 kg/m, d 0.05 m) (8 - 1025 pi 0.05^2 / 4) 9.81 = 58.78 N/m, half of
// it lumped at the body's station: the one link holds T = 155.9 + 2 x 58.78 = 273.5 N and is
// 4 (1 + T / EA) = 4.547 m long (EA = 2000 N), straight down from the anchor.
TEST(MoorDynConvert, BodyGivenAboveItsAnchorHangsBelowIt) {
  const Converted c = Convert(ReadMoorDynFile(kDir + "body_above_anchor.txt"));
  const Model sys = BuildModel(ParseScene(c.text, "above.toml"));
  EXPECT_THROW(SolveEquilibrium(sys), Error);  // what made this needed
  StepOptions step;
  step.scheme = Scheme::kImplicit;
  step.tolerance = 1e-6 * 4.0;  // the default: 1e-6 of the line's length [m]
  EquilibriumReport report;
  const std::vector<State> states =
      SolveRelaxing(sys, step, &report);
  EXPECT_GT(report.relaxed, 0.0);
  const double wet_line = (8.0 - 1025.0 * M_PI * 0.05 * 0.05 / 4) * 9.81;  // [N/m]
  const double body = (20.0 - 1025.0 * 0.004) * 9.81;                      // [N]
  const double below = 4.0 * (1 + (body + 2.0 * wet_line) / 2000.0);       // [m]
  const Vec6& pose = report.body_poses[0];
  // Statics to 1e-9 of the load: T to 3e-7 N, the length to 1e-9 m; 1e-6 m.
  EXPECT_NEAR(pose[kVertical], -5.0 - below, 1e-6);
  EXPECT_NEAR(pose[0], 0.0, 1e-6);
  EXPECT_NEAR(pose[2], 0.0, 1e-6);
  ASSERT_EQ(states.size(), 1u);
}

// A spar float (0.6 m of 0.8 m diameter in 20 links, four times lighter than the water it
// displaces) given standing through the surface on a stiff 1.1 m tether to a hub, which three
// bridles and chains hold to anchors on the bed. Newton from the file's positions stalled at
// the round-off of the stiff tether's tension (4.7e-6 N out of balance on the hub, whose
// lines' end forces carry 3e-5 N of round-off: coupled_equilibrium.cpp, `balanced`), and the
// relaxation then found it to 1e-9 of the load; a balance within the lines' round-off is now
// the statics' answer, as a line's own is (it did not balance with the run's rho_inf = 0.5).
// The answer is an equilibrium: the anchors' horizontal loads cancel (nothing else pushes
// sideways: no current), the float lies at the surface (stations above and below the still
// water level) and the hub hangs under it.
TEST(MoorDynConvert, FloatAtTheSurfaceIsRelaxedIntoEquilibrium) {
  const Converted c = Convert(ReadMoorDynFile(kDir + "float_on_bridles.txt"));
  const Model sys = BuildModel(ParseScene(c.text, "float.toml"));
  StepOptions step;
  step.scheme = Scheme::kImplicit;
  step.tolerance = 1e-6 * 16.0;  // the default: 1e-6 of the longest line's length [m]
  EquilibriumReport report;
  const std::vector<State> states =
      SolveRelaxing(sys, step, &report);
  // Within the tolerance, or the round-off the lines' end forces carry (half of each line's
  // floor, summed: what `balanced` allows a point).
  double floors = 0;  // [N]
  for (const LineEquilibriumReport& line : report.lines) floors += 0.5 * line.roundoff_floor;
  EXPECT_LE(report.residual, std::max(1e-9 * report.force_scale, floors));
  EXPECT_LT(report.residual, 2e-9 * report.force_scale);
  cablefilm::Vec anchors = cablefilm::Vec::Zero();  // the lines' pull on the fixed points [N]
  for (std::size_t i = 0; i < sys.lines.size(); ++i)
    for (int e = 0; e < 2; ++e) {
      if (sys.points[sys.line_points[i][e]].kind != PointKind::kFixed) continue;
      const int j = e == 0 ? 0 : sys.lines[i].line.links;
      anchors += StaticStationForce(sys.lines[i], states[i], j);
    }
  std::printf("[ float ] relaxed %.1f s, out-of-balance %.3g N of %.4g N; anchors' load "
              "(%.4g, %.4g, %.4g) N; float from y = %.3f to %.3f m, hub at y = %.3f m\n",
              report.relaxed, report.residual, report.force_scale, anchors[0], anchors[1],
              anchors[2], states[0].x.row(kVertical).minCoeff(),
              states[0].x.row(kVertical).maxCoeff(), states[1].x(kVertical, 0));
  // Each station balances to 1e-9 of the load (3e-6 N), the sum over the system's 70-odd
  // within 1e-6 of it.
  EXPECT_NEAR(anchors[0], 0.0, 1e-6 * report.force_scale);
  EXPECT_NEAR(anchors[2], 0.0, 1e-6 * report.force_scale);
  const Eigen::RowVectorXd y = states[0].x.row(kVertical);
  EXPECT_GT(y.maxCoeff(), 0.0);
  EXPECT_LT(y.minCoeff(), 0.0);
  EXPECT_LT(states[1].x(kVertical, 0), y.minCoeff());  // the hub (the tether's start) below
}

// The statics of a MoorDyn file's system, as `run` finds them with the default tolerance (1e-6
// of the longest line [m]): the Error's message when it has none; empty when it has.
std::string StaticsFailure(const MoorDynSystem& file) {
  const Model sys = BuildModel(ParseScene(Convert(file).text, "file.toml"));
  double longest = 0;  // [m]
  for (const LineModel& m : sys.lines) longest = std::max(longest, m.line.total_length());
  StepOptions step;
  step.scheme = Scheme::kImplicit;
  step.tolerance = 1e-6 * longest;
  try {
    SolveRelaxing(sys, step, nullptr);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

// The float file with its float cut into 40 links has no converged statics (a limit left
// open: the float's stations lying slack in the surface, each free along it, docs/model.md):
// the error names the line and says what was tried, and gives no advice the file cannot take.
// It once ended with the one-line scenes' "[initial] state = \"straight\"", which a system
// refuses (scene_parser.cpp) and a MoorDyn file cannot say.
TEST(MoorDynConvert, SystemStaticsErrorGivesNoOneLineAdvice) {
  MoorDynSystem file = ReadMoorDynFile(kDir + "float_on_bridles.txt");
  ASSERT_EQ(file.lines[0].type, "float");
  file.lines[0].segments = 40;
  const std::string msg = StaticsFailure(file);
  if (msg.empty()) GTEST_SKIP() << "the 40-link float's statics converge now: find another case";
  EXPECT_NE(msg.find("line \"1\": no static equilibrium"), std::string::npos) << msg;
  EXPECT_NE(msg.find("nor from where the system's own motion"), std::string::npos) << msg;
  EXPECT_EQ(msg.find("[initial]"), std::string::npos) << msg;
}

// A fuzzed file's: the three-leg spread with its clump's chain (leg 3) cut to 0.1 mm of 20
// links, 400 m from the clump. Newton cannot balance the clump, and the relaxation's motion
// (the chain's 5 um links stretched four million times) falls to steps of 7e-10 s: its first
// 0.1 s span alone would take millions of them, minutes of a run that never looked at its
// bounds between spans. Each span now has what is left of them: the statics fail within
// the bounds, saying how the motion ended.
TEST(MoorDynConvert, RelaxationWhoseStepsCrawlEndsWithinItsBounds) {
  MoorDynSystem file = ReadMoorDynFile(kDir + "three_leg_spread.txt");
  ASSERT_EQ(file.lines.size(), 4u);
  file.lines[2].length = 1e-4;  // [m]
  const std::string msg = StaticsFailure(file);
  EXPECT_NE(msg.find("the motion failed: the implicit steps reached their bound"),
            std::string::npos) << msg;
}

TEST(MoorDynConvert, ShippedScenesAsMoorDynFiles) {
  ExpectSameScene("catenary.txt", "catenary.toml");
  ExpectSameScene("hanging_chain.txt", "hanging_chain.toml");
  ExpectSameScene("taut_string.txt", "taut_string.toml");
}

}  // namespace
}  // namespace cablefilm
