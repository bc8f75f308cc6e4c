#include "scene/moordyn_rows.h"

#include <cctype>

#include "scene/scene_limits.h"

namespace cablefilm {

const std::vector<std::string> kMoorDynLineTypeColumns = {
    "TypeName", "Diam", "Mass/m", "EA", "BA/-zeta", "EI", "Cd",
    "Ca",       "CdAx", "CaAx",   "Cl", "dF",       "cF"};
const std::vector<std::string> kMoorDynBodyColumns = {
    "ID", "Attachment", "X0", "Y0", "Z0", "r0", "p0", "y0", "Mass", "CG", "I", "Volume", "CdA",
    "Ca"};
const std::vector<std::string> kMoorDynPointColumns = {
    "ID", "Attachment", "X", "Y", "Z", "Mass", "Volume", "CdA", "Ca"};
const std::vector<std::string> kMoorDynPointForceColumns = {
    "ID", "Attachment", "X", "Y", "Z", "Mass", "Volume", "FX", "FY", "FZ", "CdA", "Ca"};
const std::vector<std::string> kMoorDynLineColumns = {
    "ID", "LineType", "AttachA", "AttachB", "UnstrLen", "NumSegs", "LineOutputs"};

namespace {

// The ranges of the scene keys each value becomes (scene_limits.h), in words for messages.
const char* kCoordinate = "a coordinate in m from -1e6 to 1e6";
const char* kCoefficient = "a coefficient from 0 to 1000";
const char* kMass = "a mass in kg from 0 to 1e9";
const char* kVolume = "a volume in m^3 from 0 to 1e6";
const char* kDragArea = "an area in m^2 from 0 to 1e6";
constexpr double kMaxStiffness = 1e15;  // N (EA), N m^2 (EI): beyond any rope or chain

std::string Upper(std::string text) {
  for (char& c : text) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return text;
}

// MoorDyn's attachment words: letters, then an optional number, then optional letters
// ("Body2", "R1A", "P4").
struct Word {
  std::string letters, digits, rest;
};
Word Split(const std::string& text) {
  const std::string up = Upper(text);
  std::size_t i = 0;
  while (i < up.size() && std::isalpha(static_cast<unsigned char>(up[i]))) ++i;
  std::size_t j = i;
  while (j < up.size() && std::isdigit(static_cast<unsigned char>(up[j]))) ++j;
  return {up.substr(0, i), up.substr(i, j - i), up.substr(j)};
}

bool IsOneOf(const std::string& word, const std::vector<std::string>& names) {
  for (const auto& n : names)
    if (word == n) return true;
  return false;
}

// IDs are sequential from 1 within each section (MoorDyn numbers its objects by them).
void CheckId(const MoorDynRow& row, int expected) {
  int id = 0;
  if (ParseMoorDynWhole(row.Text(0), &id) && id == expected) return;
  row.Fail(0, std::to_string(expected) + " (IDs are sequential from 1" +
                  (expected == 1 ? "; the two lines after a table's header are its column "
                                   "names and units, never read)"
                                 : ")"));
}

double Coefficient(const MoorDynRow& row, std::size_t column) {
  return row.Number(column, 0, kMaxCoefficient, kCoefficient);
}

// EA: a number. MoorDyn also takes "EAs|EAd" (and "EAs|EAd_c|EAd_Lm"), its viscoelastic
// synthetic-rope model, and a file name, a stress-strain table: neither is modelled here.
double ReadEa(const MoorDynRow& row) {
  const bool bars = row.Text(3).find('|') != std::string::npos;
  return row.Number(3, 1e-9, kMaxStiffness,
                    bars ? "a single EA in N (viscoelastic EAs|EAd lines are not supported)"
                         : "a number > 0 in N, at most 1e15 (EA; a stress-strain table file "
                           "is not supported)");
}

double ReadBa(const MoorDynRow& row) {
  const bool bars = row.Text(4).find('|') != std::string::npos;
  return row.Number(4, -kMaxDampingRatio, kMaxAxialDamping,
                    bars ? "a single BA in N s or -zeta (BAs|BAd is not supported)"
                         : "BA in N s from 0 to 1e15, or -zeta from -100 to 0 (a table file is "
                           "not supported)");
}

MoorDynAttachment BodyAttachment(const MoorDynRow& row) {
  const std::string word = Upper(row.Text(1));
  if (IsOneOf(word, {"FIXED", "FIX", "ANCHOR"})) return MoorDynAttachment::kFixed;
  if (IsOneOf(word, {"COUPLED", "VESSEL", "VES", "CPLD"})) return MoorDynAttachment::kCoupled;
  if (word == "FREE") return MoorDynAttachment::kFree;
  row.Fail(1, "Fixed, Free or Coupled (or Vessel)");
}

MoorDynAttachment PointAttachment(const MoorDynRow& row, int* body) {
  const Word w = Split(row.Text(1));
  if (w.digits.empty() && w.rest.empty()) {
    if (IsOneOf(w.letters, {"FIXED", "FIX", "ANCHOR"})) return MoorDynAttachment::kFixed;
    if (IsOneOf(w.letters, {"COUPLED", "VESSEL", "VES", "CPLD", "FAIRLEAD"}))
      return MoorDynAttachment::kCoupled;
    if (IsOneOf(w.letters, {"FREE", "POINT", "CONNECT", "CON"})) return MoorDynAttachment::kFree;
  }
  if (w.letters == "BODY" && w.rest.empty() && ParseMoorDynWhole(w.digits, body) && *body >= 1)
    return MoorDynAttachment::kBody;
  row.Fail(1, "Fixed, Free, Coupled (or Vessel) or Body#N (N a body's ID, e.g. Body1)");
}

// AttachA, AttachB: a point's ID, bare or as P#, Point#, C#, Con#; R#A, R#B are rod ends.
int PointReference(const MoorDynRow& row, std::size_t column) {
  const Word w = Split(row.Text(column));
  if (IsOneOf(w.letters, {"R", "ROD"}) && !w.digits.empty())
    row.Refuse(column, "a rod end (" + row.Text(column) + "): rods are not supported yet; "
                       "expected a point's ID");
  int id = 0;
  if (IsOneOf(w.letters, {"", "P", "POINT", "C", "CON"}) && w.rest.empty() &&
      ParseMoorDynWhole(w.digits, &id) && id >= 1)
    return id;
  row.Fail(column, "a point's ID (a whole number >= 1, or P# with # the ID)");
}

std::array<double, 3> Triple(const MoorDynRow& row, std::size_t first, double lo, double hi,
                             const char* what) {
  return {row.Number(first, lo, hi, what), row.Number(first + 1, lo, hi, what),
          row.Number(first + 2, lo, hi, what)};
}

}  // namespace

MoorDynLineType ReadMoorDynLineType(const MoorDynRow& row) {
  MoorDynLineType t;
  t.line = row.line();
  t.name = row.Text(0);
  t.diameter = row.Number(1, kMinDiameter, kMaxDiameter, "a diameter in m from 1e-6 to 100");
  t.mass_per_length = row.Number(2, kMinMassPerLength, kMaxMassPerLength,
                                 "a mass per length in kg/m from 1e-9 to 1e6");
  t.ea = ReadEa(row);
  t.ba = ReadBa(row);
  t.ei = row.Number(5, 0, kMaxStiffness,
                    "a number >= 0 in N m^2, at most 1e15 (EI; a table file is not supported)");
  t.cd = Coefficient(row, 6);
  t.ca = Coefficient(row, 7);
  t.cd_ax = Coefficient(row, 8);
  t.ca_ax = Coefficient(row, 9);
  if (row.size() > 10) t.cl = Coefficient(row, 10);
  for (std::size_t c = 11; c < row.size() && c < 13; ++c) Coefficient(row, c);  // dF, cF
  return t;
}

MoorDynBody ReadMoorDynBody(const MoorDynRow& row, int id) {
  CheckId(row, id);
  MoorDynBody b;
  b.line = row.line();
  b.id = id;
  b.attachment = BodyAttachment(row);
  b.position = Triple(row, 2, -kMaxLength, kMaxLength, kCoordinate);
  b.rotation = Triple(row, 5, -360, 360, "an angle in degrees from -360 to 360");
  b.mass = row.Number(8, 0, kMaxWeightMass, kMass);
  const std::vector<double> cg =
      row.Numbers(9, {1, 3}, -kMaxLength, kMaxLength, "one number (z) or x|y|z, in m");
  b.cg = cg.size() == 1 ? std::array<double, 3>{0, 0, cg[0]}
                        : std::array<double, 3>{cg[0], cg[1], cg[2]};
  const std::vector<double> inertia =
      row.Numbers(10, {1, 3}, 0, kMaxStiffness, "one number or Ixx|Iyy|Izz, in kg m^2 >= 0");
  for (int i = 0; i < 3; ++i) b.inertia[i] = inertia[inertia.size() == 1 ? 0 : i];
  b.volume = row.Number(11, 0, kMaxVolume, kVolume);
  const std::vector<double> cda =
      row.Numbers(12, {1, 2, 3, 6}, 0, kMaxDragArea, "1, 2, 3 or 6 areas in m^2 >= 0");
  for (int i = 0; i < 6; ++i)  // MoorDyn's spreading of 1, 2, 3 or 6 values over the 6 DOF
    b.cda[i] = cda.size() == 1 ? cda[0]
               : cda.size() == 2 ? cda[i / 3]
               : cda.size() == 3 ? cda[i % 3]
                                 : cda[i];
  const std::vector<double> ca = row.Numbers(13, {1, 3}, 0, kMaxCoefficient,
                                             "one coefficient or three (x|y|z), 0 to 1000");
  for (int i = 0; i < 3; ++i) b.ca[i] = ca[ca.size() == 1 ? 0 : i];
  return b;
}

MoorDynPoint ReadMoorDynPoint(const MoorDynRow& row, int id, std::vector<std::string>* warnings) {
  CheckId(row, id);
  MoorDynPoint p;
  p.line = row.line();
  p.id = id;
  p.attachment = PointAttachment(row, &p.body);
  p.position = Triple(row, 2, -kMaxLength, kMaxLength, kCoordinate);
  p.mass = row.Number(5, 0, kMaxWeightMass, kMass);
  p.volume = row.Number(6, 0, kMaxVolume, kVolume);
  const bool forces = row.size() >= 12;  // the older form with FX FY FZ (MoorDyn reads both)
  if (forces) {
    p.force = Triple(row, 7, -1e15, 1e15, "a force in N from -1e15 to 1e15");
    if (p.force != std::array<double, 3>{})
      warnings->push_back(row.Note("its steady force FX FY FZ is not imported"));
  }
  p.cda = row.Number(forces ? 10 : 7, 0, kMaxDragArea, kDragArea);
  p.ca = Coefficient(row, forces ? 11 : 8);
  return p;
}

MoorDynLine ReadMoorDynLine(const MoorDynRow& row, int id) {
  CheckId(row, id);
  MoorDynLine l;
  l.line = row.line();
  l.id = id;
  l.type = row.Text(1);
  l.point_a = PointReference(row, 2);
  l.point_b = PointReference(row, 3);
  l.length = row.Number(4, kMinSectionLength, kMaxLength, "a length in m from 1e-6 to 1e6");
  l.segments = row.Whole(5, 1, static_cast<int>(kMaxLinks));
  return l;
}

}  // namespace cablefilm
