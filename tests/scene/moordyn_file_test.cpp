// Issue 20, MoorDyn's input files: a hand-written MoorDyn v2 file read into its structs, value
// by value; each malformed input refused with an Error that names the file, the line, the
// section, the row and the column, and says what was expected.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/error.h"
#include "scene/moordyn_file.h"

namespace cablefilm {
namespace {

const std::string kDir = CABLEFILM_SOURCE_DIR "/tests/scenes/moordyn/";

// The file's numbers are written in decimal as the test reads them: exact comparisons.
TEST(MoorDynFile, ReadsTheThreeLegSpread) {
  const MoorDynSystem s = ReadMoorDynFile(kDir + "three_leg_spread.txt");
  EXPECT_EQ(s.title, "Three-leg spread mooring in 150 m of water, a clump weight on leg 3 "
                     "(cablefilm's reader test)");
  ASSERT_EQ(s.line_types.size(), 2u);
  const MoorDynLineType& chain = s.line_types[0];
  EXPECT_EQ(chain.name, "chain");
  EXPECT_EQ(chain.line, 8);
  EXPECT_EQ(chain.diameter, 0.137);
  EXPECT_EQ(chain.mass_per_length, 115.0);
  EXPECT_EQ(chain.ea, 5.4e8);
  EXPECT_EQ(chain.ba, -0.8);
  EXPECT_EQ(chain.ei, 0.0);
  EXPECT_EQ(chain.cd, 2.4);
  EXPECT_EQ(chain.ca, 1.0);
  EXPECT_EQ(chain.cd_ax, 0.4);
  EXPECT_EQ(chain.ca_ax, 0.5);
  EXPECT_EQ(s.line_types[1].name, "wire");
  EXPECT_EQ(s.line_types[1].ba, 1.0e5);  // the trailing "# spiral strand" is a comment

  ASSERT_EQ(s.points.size(), 7u);
  EXPECT_EQ(s.points[0].attachment, MoorDynAttachment::kFixed);
  EXPECT_EQ(s.points[1].position, (std::array<double, 3>{-400.0, 692.8203, -150.0}));
  EXPECT_EQ(s.points[3].attachment, MoorDynAttachment::kCoupled);
  EXPECT_EQ(s.points[4].attachment, MoorDynAttachment::kCoupled);  // "Vessel"
  EXPECT_EQ(s.points[5].line, 19);  // after a blank line
  const MoorDynPoint& clump = s.points[6];
  EXPECT_EQ(clump.id, 7);
  EXPECT_EQ(clump.attachment, MoorDynAttachment::kFree);
  EXPECT_EQ(clump.position, (std::array<double, 3>{-220.0, -381.0512, -140.0}));
  EXPECT_EQ(clump.mass, 5000.0);
  EXPECT_EQ(clump.volume, 0.5);
  EXPECT_EQ(clump.cda, 2.0);
  EXPECT_EQ(clump.ca, 1.0);

  ASSERT_EQ(s.lines.size(), 4u);
  EXPECT_EQ(s.lines[0].type, "chain");
  EXPECT_EQ(s.lines[0].point_a, 1);
  EXPECT_EQ(s.lines[0].point_b, 4);
  EXPECT_EQ(s.lines[0].length, 850.0);
  EXPECT_EQ(s.lines[0].segments, 40);
  const MoorDynLine& wire = s.lines[3];
  EXPECT_EQ(wire.line, 27);
  EXPECT_EQ(wire.type, "wire");
  EXPECT_EQ(wire.point_a, 7);  // written "P7"
  EXPECT_EQ(wire.point_b, 6);
  EXPECT_EQ(wire.length, 450.0);
  EXPECT_EQ(wire.segments, 30);

  EXPECT_EQ(s.options.size(), 9u);
  EXPECT_EQ(s.options.at("WtrDpth").text, "150");
  EXPECT_EQ(s.options.at("WtrDpth").line, 33);
  EXPECT_EQ(s.options.at("kBot").text, "3.0e6");
  EXPECT_EQ(s.options.at("dtM").text, "0.001");
  EXPECT_EQ(s.options.at("FrictionCoefficient").text, "0.5");
  EXPECT_EQ(s.options.at("TmaxIC").text, "60");
  ASSERT_EQ(s.warnings.size(), 1u);  // OUTPUTS, not read
  EXPECT_NE(s.warnings[0].find("three_leg_spread.txt:38: OUTPUTS not read"), std::string::npos);
}

// A small valid file; the error tests change one line of it. Its lines, by number:
//  5 the line type, 9 and 10 the points, 14 the line, 16 the option, 17 the last.
const std::string kBase = R"(Test system
---------------------- LINE TYPES -----------------------
TypeName Diam Mass/m EA BA/-zeta EI Cd Ca CdAx CaAx
(name) (m) (kg/m) (N) (N-s/-) (N-m^2) (-) (-) (-) (-)
chain 0.1 150.0 1e8 -1 0 2.3 1 0 0
---------------------- POINTS ---------------------------
ID Attachment X Y Z Mass Volume CdA Ca
(#) (-) (m) (m) (m) (kg) (m^3) (m^2) (-)
1 Fixed -500 0 -150 0 0 0 0
2 Coupled 0 0 -9 0 0 0 0
---------------------- LINES ----------------------------
ID LineType AttachA AttachB UnstrLen NumSegs LineOutputs
(#) (name) (#) (#) (m) (-) (-)
1 chain 1 2 550 20 -
---------------------- OPTIONS --------------------------
150 WtrDpth
----------------------- need this line ------------------
)";

std::string Replace(const std::string& text, const std::string& from, const std::string& to) {
  std::string out = text;
  const std::size_t at = out.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) out.replace(at, from.size(), to);
  return out;
}

// The Error of reading `text` as sys.txt; "" if there is none.
std::string ErrorOf(const std::string& text) {
  try {
    ReadMoorDynText(text, "sys.txt");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

void ExpectError(const std::string& text, const std::string& begins, const std::string& has) {
  const std::string what = ErrorOf(text);
  EXPECT_EQ(what.substr(0, begins.size()), begins) << what;
  EXPECT_NE(what.find(has), std::string::npos) << what;
}

TEST(MoorDynFile, TheBaseFileReads) {
  const MoorDynSystem s = ReadMoorDynText(kBase, "sys.txt");
  EXPECT_EQ(s.title, "Test system");
  EXPECT_EQ(s.lines.size(), 1u);
  EXPECT_TRUE(s.warnings.empty());
}

TEST(MoorDynFile, MissingColumn) {
  ExpectError(Replace(kBase, "1 chain 1 2 550 20 -", "1 chain 1 2 550"),
              "sys.txt:14: LINES row 1, column NumSegs: missing; expected 7 columns "
              "(ID LineType AttachA AttachB UnstrLen NumSegs LineOutputs), got 5", "");
  // A v1 line type (9 columns, another order) is not a v2 one.
  ExpectError(Replace(kBase, "chain 0.1 150.0 1e8 -1 0 2.3 1 0 0", "chain 0.1 150 1e8 -1 1 0 2 0"),
              "sys.txt:5: LINE TYPES row 1, column CaAx: missing; expected 10 columns", "got 9");
}

TEST(MoorDynFile, NotANumber) {
  ExpectError(Replace(kBase, "1 chain 1 2 550 20 -", "1 chain 1 2 550 x -"),
              "sys.txt:14: LINES row 1, column NumSegs: expected a whole number from 1 to "
              "10000000, got \"x\"", "");
  ExpectError(Replace(kBase, "1 Fixed -500 0 -150", "1 Fixed -500 abc -150"),
              "sys.txt:9: POINTS row 1, column Y: expected a coordinate in m from -1e6 to 1e6, "
              "got \"abc\"", "");
  ExpectError(Replace(kBase, "chain 0.1 150.0", "chain 0.1 nan"),
              "sys.txt:5: LINE TYPES row 1, column Mass/m: expected a mass per length in kg/m",
              "got \"nan\"");
  ExpectError(Replace(kBase, "chain 0.1 150.0", "chain 0.1 1e999"),
              "sys.txt:5: LINE TYPES row 1, column Mass/m: expected", "got \"1e999\"");
}

TEST(MoorDynFile, NumberOutOfRange) {
  ExpectError(Replace(kBase, "chain 0.1 150.0", "chain -0.1 150.0"),
              "sys.txt:5: LINE TYPES row 1, column Diam: expected a diameter in m from 1e-6 to "
              "100, got \"-0.1\"", "");
  ExpectError(Replace(kBase, "2 Coupled 0 0 -9 0 0 0 0", "2 Coupled 0 0 -9 -5 0 0 0"),
              "sys.txt:10: POINTS row 2, column Mass: expected a mass in kg from 0 to 1e9",
              "got \"-5\"");
  ExpectError(Replace(kBase, "chain 0.1 150.0 1e8 -1", "chain 0.1 150.0 1e8 -101"),
              "sys.txt:5: LINE TYPES row 1, column BA/-zeta: expected", "got \"-101\"");
}

TEST(MoorDynFile, UnknownLineType) {
  ExpectError(Replace(kBase, "1 chain 1 2", "1 chian 1 2"),
              "sys.txt:14: LINES row 1, column LineType: expected the name of a line type of "
              "LINE TYPES (\"chain\"), got \"chian\"", "");
}

TEST(MoorDynFile, UndefinedPoint) {
  ExpectError(Replace(kBase, "1 chain 1 2", "1 chain 1 3"),
              "sys.txt:14: LINES row 1, column AttachB: point 3 is not defined; expected a "
              "point's ID from 1 to 2 (POINTS)", "");
  ExpectError(Replace(kBase, "1 chain 1 2", "1 chain X1 2"),
              "sys.txt:14: LINES row 1, column AttachA: expected a point's ID", "got \"X1\"");
}

TEST(MoorDynFile, UndefinedBody) {
  ExpectError(Replace(kBase, "2 Coupled", "2 Body2"),
              "sys.txt:10: POINTS row 2, column Attachment: body 2 is not defined; expected a "
              "body of BODIES (the file has none)", "");
  ExpectError(Replace(kBase, "2 Coupled", "2 Floating"),
              "sys.txt:10: POINTS row 2, column Attachment: expected Fixed, Free, Coupled (or "
              "Vessel) or Body#N", "got \"Floating\"");
}

TEST(MoorDynFile, IdsAreSequential) {
  ExpectError(Replace(kBase, "2 Coupled", "3 Coupled"),
              "sys.txt:10: POINTS row 2, column ID: expected 2 (IDs are sequential from 1), got "
              "\"3\"", "");
  // A table without its units line: its first row is taken as the units and never read.
  ExpectError(Replace(kBase, "(#) (-) (m) (m) (m) (kg) (m^3) (m^2) (-)\n", ""),
              "sys.txt:9: POINTS row 1, column ID: expected 1 (IDs are sequential from 1; the "
              "two lines after a table's header are its column names and units", "");
}

TEST(MoorDynFile, ViscoelasticStiffnessIsRefused) {
  ExpectError(Replace(kBase, "chain 0.1 150.0 1e8", "chain 0.1 150.0 1e8|2e8"),
              "sys.txt:5: LINE TYPES row 1, column EA: expected a single EA in N (viscoelastic "
              "EAs|EAd lines are not supported), got \"1e8|2e8\"", "");
  ExpectError(Replace(kBase, "chain 0.1 150.0 1e8", "chain 0.1 150.0 poly_ea.txt"),
              "sys.txt:5: LINE TYPES row 1, column EA: expected a number > 0 in N",
              "a stress-strain table file is not supported");
}

TEST(MoorDynFile, RodsAreRefused) {
  const std::string rods =
      "---------------------- RODS ---------------------------\n"
      "ID RodType Attachment Xa Ya Za Xb Yb Zb NumSegs RodOutputs\n"
      "(#) (name) (word/ID) (m) (m) (m) (m) (m) (m) (-) (-)\n"
      "1 Can Fixed 0 0 -10 0 0 -5 4 -\n";
  ExpectError(Replace(kBase, "---------------------- LINES", rods + "---------------------- LINES"),
              "sys.txt:14: RODS row 1: rods are not supported yet", "");
  ExpectError(Replace(kBase, "1 chain 1 2", "1 chain R1A 2"),
              "sys.txt:14: LINES row 1, column AttachA: a rod end (R1A): rods are not "
              "supported yet", "");
}

TEST(MoorDynFile, EmptyFileAndNoLines) {
  ExpectError("", "sys.txt:1: the file is empty; expected a MoorDyn v2 input file", "");
  ExpectError(" \n\t\n", "sys.txt:1: the file is empty", "");
  const std::string lines =
      "---------------------- LINES ----------------------------\n"
      "ID LineType AttachA AttachB UnstrLen NumSegs LineOutputs\n"
      "(#) (name) (#) (#) (m) (-) (-)\n"
      "1 chain 1 2 550 20 -\n";
  ExpectError(Replace(kBase, lines, ""), "sys.txt:13: no LINES section; expected", "");
  ExpectError(Replace(kBase, "1 chain 1 2 550 20 -\n", ""),
              "sys.txt:11: LINES has no rows; expected at least one line", "");
}

TEST(MoorDynFile, SectionsAndOptions) {
  ExpectError(Replace(kBase, "OPTIONS -", "LINE TYPES -"),
              "sys.txt:15: LINE TYPES given a second time (first at line 2)", "");
  ExpectError(Replace(kBase, "150 WtrDpth", "deep WtrDpth"),
              "sys.txt:16: OPTIONS WtrDpth: expected a number from 0 to 1e6 in m, got \"deep\"",
              "");
  ExpectError(Replace(kBase, "chain 0.1 150.0 1e8 -1 0 2.3 1 0 0",
                      "chain 0.1 150.0 1e8 -1 0 2.3 1 0 0\nchain 0.2 10 1e8 -1 0 2.3 1 0 0"),
              "sys.txt:6: LINE TYPES row 2, column TypeName: \"chain\" is already the name of "
              "the line type at line 5", "");
}

// What MoorDyn reads and cablefilm skips: kept out, each with a warning.
TEST(MoorDynFile, SkippedContentIsWarned) {
  const std::string text =
      Replace(Replace(kBase, "150 WtrDpth", "150 WtrDpth\n2 WtrDpth # again"),
              "----------------------- need this line ------------------",
              "---------------------- CONTROL ----------------------\n1 1\n"
              "----------------------- need this line ------------------\nstray text");
  const MoorDynSystem s = ReadMoorDynText(text, "sys.txt");
  EXPECT_EQ(s.options.at("WtrDpth").text, "2");  // the last, as MoorDyn
  ASSERT_EQ(s.warnings.size(), 3u);
  EXPECT_NE(s.warnings[0].find("sys.txt:21: not read: it follows the closing header"),
            std::string::npos) << s.warnings[0];
  EXPECT_NE(s.warnings[1].find("sys.txt:18: section \"CONTROL\" (1 lines) skipped"),
            std::string::npos) << s.warnings[1];
  EXPECT_NE(s.warnings[2].find("sys.txt:17: OPTIONS WtrDpth given again (first at line 16)"),
            std::string::npos) << s.warnings[2];
}

// MoorDyn's other spellings: older section names, attachment words in any case, P#/Con#
// references, comments after ! and %, Windows line ends, the older 12-column points.
TEST(MoorDynFile, MoorDynSpellings) {
  std::string text = Replace(kBase, "POINTS -", "CONNECTION PROPERTIES -");
  text = Replace(text, "LINES -", "LINE LIST -");
  text = Replace(text, "2 Coupled 0 0 -9 0 0 0 0", "2 vessel 0 0 -9 0 0 0 0 0 0 0 ! a fairlead");
  text = Replace(text, "1 chain 1 2", "1 chain Con1 P2");
  text = Replace(text, "1 Fixed", "1 ANCHOR");
  text = Replace(text, "150 WtrDpth", "150 WtrDpth % water depth");
  std::string crlf;
  for (char c : text) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  const MoorDynSystem s = ReadMoorDynText(crlf, "sys.txt");
  EXPECT_EQ(s.points[0].attachment, MoorDynAttachment::kFixed);
  EXPECT_EQ(s.points[1].attachment, MoorDynAttachment::kCoupled);
  EXPECT_EQ(s.lines[0].point_a, 1);
  EXPECT_EQ(s.lines[0].point_b, 2);
  EXPECT_EQ(s.options.at("WtrDpth").text, "150");
  EXPECT_EQ(s.title, "Test system");
}

TEST(MoorDynFile, Bodies) {
  const std::string bodies =
      "---------------------- BODIES ---------------------------\n"
      "ID Attachment X0 Y0 Z0 r0 p0 y0 Mass CG* I* Volume CdA* Ca\n"
      "(#) (-) (m) (m) (m) (deg) (deg) (deg) (kg) (m) (kg-m^2) (m^3) (m^2) (-)\n"
      "1 Coupled 10 20 -5 0 0 90 1e6 0|0|-2 1e8|1e8|2e8 1000 10|20 1.0\n";
  const std::string text = Replace(Replace(kBase, "---------------------- POINTS",
                                           bodies + "---------------------- POINTS"),
                                   "2 Coupled", "2 Body1");
  const MoorDynSystem s = ReadMoorDynText(text, "sys.txt");
  ASSERT_EQ(s.bodies.size(), 1u);
  const MoorDynBody& b = s.bodies[0];
  EXPECT_EQ(b.attachment, MoorDynAttachment::kCoupled);
  EXPECT_EQ(b.position, (std::array<double, 3>{10, 20, -5}));
  EXPECT_EQ(b.rotation, (std::array<double, 3>{0, 0, 90}));
  EXPECT_EQ(b.cg, (std::array<double, 3>{0, 0, -2}));
  EXPECT_EQ(b.inertia, (std::array<double, 3>{1e8, 1e8, 2e8}));
  EXPECT_EQ(b.cda, (std::array<double, 6>{10, 10, 10, 20, 20, 20}));  // translation|rotation
  EXPECT_EQ(b.ca, (std::array<double, 3>{1, 1, 1}));
  EXPECT_EQ(s.points[1].attachment, MoorDynAttachment::kBody);
  EXPECT_EQ(s.points[1].body, 1);
  ExpectError(Replace(text, "10|20 1.0", "10|20|30|40 1.0"),
              "sys.txt:9: BODIES row 1, column CdA: expected 1, 2, 3 or 6 areas in m^2",
              "got \"10|20|30|40\"");
}

TEST(MoorDynFile, Numbers) {
  double v = 0;
  EXPECT_TRUE(ParseMoorDynNumber("384.243E6", &v));
  EXPECT_EQ(v, 384.243e6);
  EXPECT_TRUE(ParseMoorDynNumber("+2", &v));
  EXPECT_EQ(v, 2.0);
  EXPECT_TRUE(ParseMoorDynNumber("-0", &v));
  EXPECT_FALSE(std::signbit(v));
  for (const char* bad : {"", "+", "+-1", "1.0x", "0x10", "inf", "nan", "1e400", "1,5", "--1"})
    EXPECT_FALSE(ParseMoorDynNumber(bad, &v)) << bad;
}

TEST(MoorDynFile, FileErrors) {
  try {
    ReadMoorDynFile(kDir + "no_such_file.txt");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("no_such_file.txt: cannot open the MoorDyn input file"),
              std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace cablefilm
