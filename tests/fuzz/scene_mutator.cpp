// Issue 22: the scene fuzzer's structure-aware mutator, linked into the libFuzzer binary only
// (scene_fuzzer, CABLEFILM_FUZZ=ON). libFuzzer's byte mutations left 97 % of the inputs dead in
// the TOML parser; this mutator reads an input as TOML (toml++) and makes ONE change to its keys
// and values, then writes it back as TOML, so the change reaches the loader's checks, the model
// and the run:
//   - a number: a hostile or a nearby value (0, -0, its negative, 1e-300, 1e300, the largest
//     integers, the stated limits, x (1 +- 1e-12), 10 x, x / 10, nan, +-inf, ...);
//   - a string: another valid choice (a motion, a model, a material's or a point's name, ...) or
//     garbage (empty, long, control characters, paths);
//   - a key deleted, a key/value copied from one table to another, a known key of the scene
//     format (docs/scene-format.md) added with a random value, a value of another type;
//   - an entry of an array of tables ([[material]], [[cable.section]], [[point]], [[line]], ...)
//     duplicated or deleted; a [[line]]'s start or end made another point's name;
//   - an array of numbers made longer or shorter.
// The motion table after the harness's separator line (scene_fuzzer.cpp) is kept as it is, or
// (1 time in 10) byte-mutated alone. An input that is not TOML gets libFuzzer's own byte
// mutations (LLVMFuzzerMutate), and so does any input 1 time in 64, to keep the parser itself
// fuzzed. Every choice comes from the seed libFuzzer passes: a run is reproducible.
// LLVMFuzzerCustomCrossOver splices two scenes: a top-level key of one, or an entry of one of its
// arrays of tables, into the other.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include <toml++/toml.h>

extern "C" std::size_t LLVMFuzzerMutate(std::uint8_t* data, std::size_t size, std::size_t max_size);

namespace {

constexpr char kTableSeparator[] = "\n# ---- motion.csv ----\n";

using Rng = std::mt19937_64;

std::size_t Pick(Rng& rng, std::size_t n) {
  return n == 0 ? 0 : static_cast<std::size_t>(rng() % n);
}
bool OneIn(Rng& rng, std::size_t n) { return Pick(rng, n) == 0; }

// Where a node sits: in a table under a key, or in an array at an index. `path` names the
// tables it is in, without indices ("cable.section", "line.section", "" for the top level).
struct Slot {
  toml::node* node = nullptr;
  toml::table* table = nullptr;
  std::string key;
  toml::array* array = nullptr;
  std::size_t index = 0;
  std::string path;
};

struct Doc {
  std::vector<Slot> slots;                                   // every node but the root
  std::vector<std::pair<toml::table*, std::string>> tables;  // every table, with its path
  std::vector<std::pair<toml::array*, std::string>> table_arrays;  // [[...]], non-empty
  std::vector<std::string> strings;                          // every string value
};

bool IsTableArray(const toml::array& a) {
  if (a.empty()) return false;
  for (const toml::node& n : a)
    if (!n.is_table()) return false;
  return true;
}

void Walk(toml::node& node, const std::string& path, Doc& doc);

void WalkTable(toml::table& t, const std::string& path, Doc& doc) {
  doc.tables.emplace_back(&t, path);
  for (auto&& [key, value] : t) {
    Slot s;
    s.node = &value;
    s.table = &t;
    s.key = std::string(key.str());
    s.path = path;
    doc.slots.push_back(s);
    Walk(value, path.empty() ? s.key : path + "." + s.key, doc);
  }
}

void Walk(toml::node& node, const std::string& path, Doc& doc) {
  if (toml::table* t = node.as_table()) {
    WalkTable(*t, path, doc);
  } else if (toml::array* a = node.as_array()) {
    if (IsTableArray(*a)) doc.table_arrays.emplace_back(a, path);
    for (std::size_t i = 0; i < a->size(); ++i) {
      Slot s;
      s.node = a->get(i);
      s.array = a;
      s.index = i;
      s.path = path;
      doc.slots.push_back(s);
      Walk(*s.node, path, doc);
    }
  } else if (const toml::value<std::string>* v = node.as_string()) {
    doc.strings.push_back(v->get());
  }
}

// Puts `value` where the slot is.
template <typename V>
void Set(const Slot& s, V&& value) {
  if (s.table)
    s.table->insert_or_assign(s.key, std::forward<V>(value));
  else
    s.array->replace(s.array->cbegin() + static_cast<std::ptrdiff_t>(s.index),
                     std::forward<V>(value));
}

// ---- values ----

constexpr double kLimits[] = {1e-12, 1e-9, 1e-6, 1e-3, 1.0, 100.0, 1000.0, 1e5, 1e6, 1e7,
                              1e9, 1e12, 1e13, 1e15};

double HostileDouble(Rng& rng, double x) {
  const double inf = std::numeric_limits<double>::infinity();
  if (OneIn(rng, 2)) {  // nearby: mostly still within the limits, so the run is reached
    switch (Pick(rng, 8)) {
      case 0: return x * (1 + 1e-12);
      case 1: return x * (1 - 1e-12);
      case 2: return x * 10;
      case 3: return x / 10;
      case 4: return x * 2;
      case 5: return x / 2;
      case 6: return x * std::uniform_real_distribution<double>(0.5, 1.5)(rng);
      default: return std::nextafter(x, OneIn(rng, 2) ? inf : -inf);
    }
  }
  switch (Pick(rng, 24)) {
    case 0: return 0.0;
    case 1: return -0.0;
    case 2: return -x;
    case 3: return 1e-300;
    case 4: return -1e-300;
    case 5: return 1e300;
    case 6: return -1e300;
    case 7: return std::numeric_limits<double>::denorm_min();
    case 8: return std::numeric_limits<double>::max();
    case 9: return x * (1 + 1e-12);
    case 10: return x * (1 - 1e-12);
    case 11: return x * 10;
    case 12: return x / 10;
    case 13: return std::numeric_limits<double>::quiet_NaN();
    case 14: return inf;
    case 15: return -inf;
    case 16: {  // a stated limit, or just past it
      const double l = kLimits[Pick(rng, std::size(kLimits))];
      const double v = OneIn(rng, 2) ? l : l * (OneIn(rng, 2) ? 1 + 1e-12 : 1 - 1e-12);
      return OneIn(rng, 4) ? -v : v;
    }
    case 17: return x + 1;
    case 18: return x - 1;
    case 19: return x * 2;
    case 20: return x / 2;
    case 21: return std::uniform_real_distribution<double>(-1e3, 1e3)(rng);
    case 22: return std::nextafter(x, OneIn(rng, 2) ? inf : -inf);
    default: return std::ldexp(1.0, static_cast<int>(Pick(rng, 2100)) - 1075);
  }
}

std::int64_t HostileInteger(Rng& rng, std::int64_t n) {
  constexpr std::int64_t kMax = std::numeric_limits<std::int64_t>::max();
  constexpr std::int64_t kMin = std::numeric_limits<std::int64_t>::min();
  switch (Pick(rng, 16)) {
    case 0: return 0;
    case 1: return -1;
    case 2: return 1;
    case 3: return n == kMin ? kMax : -n;
    case 4: return n == kMax ? n : n + 1;
    case 5: return n == kMin ? n : n - 1;
    case 6: return (n > kMax / 10 || n < kMin / 10) ? n : n * 10;
    case 7: return n / 10;
    case 8: return kMax;
    case 9: return kMin;
    case 10: return (std::int64_t{1} << 53) + 1;
    case 11: return 10000000;
    case 12: return 10000001;
    case 13: return std::int64_t{1} << 31;
    case 14: return std::int64_t{1} << 32;
    default: return static_cast<std::int64_t>(Pick(rng, 200));
  }
}

// A plausible number for a key that has none yet.
double SomeDouble(Rng& rng) {
  constexpr double kSome[] = {0.0, 1.0, 0.5, 2.0, 10.0, 100.0, 1e-3, -1.0, -50.0, 1025.0, 9.81};
  if (OneIn(rng, 3)) return HostileDouble(rng, 1.0);
  return kSome[Pick(rng, std::size(kSome))];
}

// The choices of the scene format's string keys, by key name.
const std::vector<std::string>& Choices(const std::string& key) {
  static const std::vector<std::string> motion = {"fixed", "free", "trochoid", "table", "wave"};
  static const std::vector<std::string> model = {"elastic", "inextensible"};
  static const std::vector<std::string> state = {"equilibrium", "straight"};
  static const std::vector<std::string> integrator = {"implicit", "explicit"};
  static const std::vector<std::string> time_step = {"auto"};
  static const std::vector<std::string> colormap = {"viridis", "cividis", "magma", "inferno",
                                                    "plasma"};
  static const std::vector<std::string> view = {"auto", "2d", "3d"};
  static const std::vector<std::string> file = {"motion.csv", "ship_motion.csv"};
  static const std::vector<std::string> interpolation = {"spline", "linear"};
  static const std::vector<std::string> friction_model = {"stick_slip", "smoothed"};
  static const std::vector<std::string> none;
  if (key == "motion") return motion;
  if (key == "model") return model;
  if (key == "state") return state;
  if (key == "integrator") return integrator;
  if (key == "time_step") return time_step;
  if (key == "colormap") return colormap;
  if (key == "view") return view;
  if (key == "file") return file;
  if (key == "interpolation") return interpolation;
  if (key == "friction_model") return friction_model;
  return none;
}

std::string Garbage(Rng& rng) {
  switch (Pick(rng, 12)) {
    case 0: return "";
    case 1: return std::string(1 + Pick(rng, 3000), 'x');
    case 2: return "\x01\x1f\x7f\t\r\n";
    case 3: return "../../../../etc/passwd";
    case 4: return "/dev/zero";
    case 5: return "/";
    case 6: return ".";
    case 7: return "nonexistent.csv";
    case 8: return "\xc3\xa9\xe2\x80\xa8\xf0\x9f\x92\xa5";  // e acute, U+2028, an emoji
    case 9: return " elastic";
    case 10: return "ELASTIC";
    default: return std::string(64 + Pick(rng, 2), 'a');  // a name at the length limit
  }
}

std::string SomeString(Rng& rng, const std::string& key, const Doc& doc) {
  const std::vector<std::string>& choices = Choices(key);
  const std::size_t r = Pick(rng, 8);
  if (r < 4 && !choices.empty()) return choices[Pick(rng, choices.size())];
  if (r < 6 && !doc.strings.empty()) return doc.strings[Pick(rng, doc.strings.size())];
  if (r == 6) return "n" + std::to_string(Pick(rng, 5));
  return Garbage(rng);
}

// A value of another type than the one there (or any value, for a new key).
void SetOtherType(Rng& rng, const Slot& s, const Doc& doc) {
  switch (Pick(rng, 12)) {
    case 0: Set(s, std::string("1.0")); break;
    case 1: Set(s, true); break;
    case 2: Set(s, toml::array{}); break;
    case 3: Set(s, toml::array{1.0, 2.0, 3.0}); break;
    case 4: Set(s, toml::array{1.0, 2.0, 3.0, 4.0}); break;
    case 5: Set(s, toml::table{{"x", 1}}); break;
    case 6: Set(s, toml::array{toml::array{1.0, 2.0}, toml::array{3.0}}); break;
    case 7: Set(s, std::int64_t{1}); break;
    case 8: Set(s, 1.5); break;
    case 9: {  // deep nesting
      toml::array a{1.0};
      const std::size_t depth = 2 + Pick(rng, 40);
      for (std::size_t i = 0; i < depth; ++i) {
        toml::array outer;
        outer.push_back(std::move(a));
        a = std::move(outer);
      }
      Set(s, std::move(a));
      break;
    }
    case 10: Set(s, SomeString(rng, s.key, doc)); break;
    default: Set(s, toml::array{std::string("a"), 1.0}); break;
  }
}

// ---- the mutations ----

bool MutateNumber(Rng& rng, Doc& doc) {
  std::vector<const Slot*> numbers;
  for (const Slot& s : doc.slots)
    if (s.node->is_number()) numbers.push_back(&s);
  if (numbers.empty()) return false;
  const Slot& s = *numbers[Pick(rng, numbers.size())];
  if (const toml::value<std::int64_t>* i = s.node->as_integer()) {
    const std::int64_t n = i->get();
    if (OneIn(rng, 6))
      Set(s, HostileDouble(rng, static_cast<double>(n)));  // a float where a whole number was
    else
      Set(s, HostileInteger(rng, n));
  } else {
    const double x = s.node->as_floating_point()->get();
    const double v = HostileDouble(rng, x);
    if (OneIn(rng, 8) && std::isfinite(v) && std::fabs(v) < 9e18)
      Set(s, static_cast<std::int64_t>(v));  // a whole number where a float was
    else
      Set(s, v);
  }
  return true;
}

bool MutateString(Rng& rng, Doc& doc) {
  std::vector<const Slot*> strings;
  for (const Slot& s : doc.slots)
    if (s.node->is_string()) strings.push_back(&s);
  if (strings.empty()) return false;
  const Slot& s = *strings[Pick(rng, strings.size())];
  Set(s, SomeString(rng, s.key, doc));
  return true;
}

bool DeleteKey(Rng& rng, Doc& doc) {
  std::vector<const Slot*> keys;
  for (const Slot& s : doc.slots)
    if (s.table) keys.push_back(&s);
  if (keys.empty()) return false;
  const Slot& s = *keys[Pick(rng, keys.size())];
  s.table->erase(s.key);
  return true;
}

bool DuplicateEntry(Rng& rng, Doc& doc) {
  if (doc.table_arrays.empty()) return false;
  toml::array& a = *doc.table_arrays[Pick(rng, doc.table_arrays.size())].first;
  const toml::table copy = *a.get(Pick(rng, a.size()))->as_table();
  a.insert(a.cbegin() + static_cast<std::ptrdiff_t>(Pick(rng, a.size() + 1)), copy);
  return true;
}

bool DeleteEntry(Rng& rng, Doc& doc) {
  if (doc.table_arrays.empty()) return false;
  toml::array& a = *doc.table_arrays[Pick(rng, doc.table_arrays.size())].first;
  a.erase(a.cbegin() + static_cast<std::ptrdiff_t>(Pick(rng, a.size())));
  return true;
}

bool CopyKey(Rng& rng, Doc& doc) {
  std::vector<const Slot*> keys;
  for (const Slot& s : doc.slots)
    if (s.table) keys.push_back(&s);
  if (keys.empty() || doc.tables.empty()) return false;
  const Slot& from = *keys[Pick(rng, keys.size())];
  toml::table& to = *doc.tables[Pick(rng, doc.tables.size())].first;
  if (&to == from.table) return false;
  to.insert_or_assign(from.key, *from.node);  // a deep copy
  return true;
}

enum class Kind { kNumber, kInteger, kString, kVector, kBool, kCurrent };
struct KnownKey {
  const char* table;  // a path; "[]" after a name: an entry of that array of tables
  const char* key;
  Kind kind;
};

// The keys of docs/scene-format.md.
constexpr KnownKey kKnownKeys[] = {
    {"", "title", Kind::kString},
    {"environment", "gravity", Kind::kNumber},
    {"environment", "fluid_density", Kind::kNumber},
    {"environment", "current", Kind::kCurrent},
    {"environment", "current_heading", Kind::kNumber},
    {"seabed", "y", Kind::kNumber},
    {"seabed", "stiffness", Kind::kNumber},
    {"seabed", "damping", Kind::kNumber},
    {"seabed", "friction", Kind::kNumber},
    {"seabed", "friction_velocity", Kind::kNumber},
    {"seabed", "friction_model", Kind::kString},
    {"seabed", "friction_stiffness", Kind::kNumber},
    {"waves", "height", Kind::kNumber},
    {"waves", "period", Kind::kNumber},
    {"waves", "depth", Kind::kNumber},
    {"waves", "surface_y", Kind::kNumber},
    {"waves", "phase", Kind::kNumber},
    {"waves", "heading", Kind::kNumber},
    {"waves", "ramp_rate", Kind::kNumber},
    {"waves", "kinematics", Kind::kString},
    {"material[]", "name", Kind::kString},
    {"material[]", "diameter", Kind::kNumber},
    {"material[]", "area", Kind::kNumber},
    {"material[]", "mass_per_length", Kind::kNumber},
    {"material[]", "youngs_modulus", Kind::kNumber},
    {"material[]", "drag_coefficient", Kind::kNumber},
    {"material[]", "added_mass_coefficient", Kind::kNumber},
    {"material[]", "axial_damping", Kind::kNumber},
    {"material[]", "axial_damping_ratio", Kind::kNumber},
    {"material[]", "tangential_drag_coefficient", Kind::kNumber},
    {"material[]", "tangential_added_mass_coefficient", Kind::kNumber},
    {"material[]", "axial_froude_krylov", Kind::kBool},
    {"material[]", "minimum_breaking_load", Kind::kNumber},
    {"cable", "model", Kind::kString},
    {"cable.section[]", "material", Kind::kString},
    {"cable.section[]", "length", Kind::kNumber},
    {"cable.section[]", "segments", Kind::kInteger},
    {"cable.weight[]", "at", Kind::kNumber},
    {"cable.weight[]", "mass", Kind::kNumber},
    {"cable.weight[]", "volume", Kind::kNumber},
    {"cable.weight[]", "added_volume", Kind::kVector},
    {"cable.weight[]", "drag_coefficient", Kind::kVector},
    {"cable.weight[]", "drag_area", Kind::kVector},
    {"ends.start", "position", Kind::kVector},
    {"ends.start", "motion", Kind::kString},
    {"ends.start", "x_amplitudes", Kind::kVector},
    {"ends.start", "y_amplitudes", Kind::kVector},
    {"ends.start", "z_amplitudes", Kind::kVector},
    {"ends.start", "period", Kind::kNumber},
    {"ends.start", "ramp_rate", Kind::kNumber},
    {"ends.start", "file", Kind::kString},
    {"ends.start", "interpolation", Kind::kString},
    {"ends.start", "x_rao", Kind::kVector},
    {"ends.start", "y_rao", Kind::kVector},
    {"ends.start", "z_rao", Kind::kVector},
    {"ends.end", "position", Kind::kVector},
    {"ends.end", "motion", Kind::kString},
    {"ends.end", "x_amplitudes", Kind::kVector},
    {"ends.end", "y_amplitudes", Kind::kVector},
    {"ends.end", "z_amplitudes", Kind::kVector},
    {"ends.end", "period", Kind::kNumber},
    {"ends.end", "ramp_rate", Kind::kNumber},
    {"ends.end", "file", Kind::kString},
    {"ends.end", "interpolation", Kind::kString},
    {"ends.end", "x_rao", Kind::kVector},
    {"ends.end", "y_rao", Kind::kVector},
    {"ends.end", "z_rao", Kind::kVector},
    {"initial", "state", Kind::kString},
    {"simulation", "duration", Kind::kNumber},
    {"simulation", "integrator", Kind::kString},
    {"simulation", "time_step", Kind::kNumber},
    {"simulation", "tolerance", Kind::kNumber},
    {"simulation", "rho_infinity", Kind::kNumber},
    {"simulation", "start_tolerance", Kind::kNumber},
    {"simulation", "start_duration", Kind::kNumber},
    {"simulation", "safety_factor", Kind::kNumber},
    {"film", "width", Kind::kInteger},
    {"film", "height", Kind::kInteger},
    {"film", "fps", Kind::kNumber},
    {"film", "speed", Kind::kNumber},
    {"film", "crf", Kind::kInteger},
    {"film", "colormap", Kind::kString},
    {"film", "tension_range", Kind::kVector},
    {"film", "view", Kind::kString},
    {"output", "interval", Kind::kNumber},
    {"output", "film", Kind::kBool},
    {"output", "frames", Kind::kBool},
    {"point[]", "name", Kind::kString},
    {"point[]", "position", Kind::kVector},
    {"point[]", "motion", Kind::kString},
    {"point[]", "x_amplitudes", Kind::kVector},
    {"point[]", "y_amplitudes", Kind::kVector},
    {"point[]", "z_amplitudes", Kind::kVector},
    {"point[]", "period", Kind::kNumber},
    {"point[]", "ramp_rate", Kind::kNumber},
    {"point[]", "file", Kind::kString},
    {"point[]", "interpolation", Kind::kString},
    {"point[]", "x_rao", Kind::kVector},
    {"point[]", "y_rao", Kind::kVector},
    {"point[]", "z_rao", Kind::kVector},
    {"point[]", "mass", Kind::kNumber},
    {"point[]", "volume", Kind::kNumber},
    {"point[]", "added_volume", Kind::kVector},
    {"point[]", "drag_coefficient", Kind::kVector},
    {"point[]", "drag_area", Kind::kVector},
    {"point[]", "force", Kind::kVector},
    {"body[]", "name", Kind::kString},
    {"body[]", "position", Kind::kVector},
    {"body[]", "orientation", Kind::kVector},
    {"body[]", "motion", Kind::kString},
    {"body[]", "x_amplitudes", Kind::kVector},
    {"body[]", "rx_amplitudes", Kind::kVector},
    {"body[]", "ry_amplitudes", Kind::kVector},
    {"body[]", "rz_amplitudes", Kind::kVector},
    {"body[]", "period", Kind::kNumber},
    {"body[]", "ramp_rate", Kind::kNumber},
    {"body[]", "file", Kind::kString},
    {"body[]", "interpolation", Kind::kString},
    {"body[]", "x_rao", Kind::kVector},
    {"body[]", "rx_rao", Kind::kVector},
    {"body[]", "ry_rao", Kind::kVector},
    {"body[]", "rz_rao", Kind::kVector},
    {"line[]", "name", Kind::kString},
    {"line[]", "start", Kind::kString},
    {"line[]", "end", Kind::kString},
    {"line[]", "model", Kind::kString},
    {"line[].section[]", "material", Kind::kString},
    {"line[].section[]", "length", Kind::kNumber},
    {"line[].section[]", "segments", Kind::kInteger},
    {"line[].weight[]", "at", Kind::kNumber},
    {"line[].weight[]", "mass", Kind::kNumber},
    {"line[].weight[]", "volume", Kind::kNumber},
    {"line[].weight[]", "added_volume", Kind::kVector},
    {"line[].weight[]", "drag_coefficient", Kind::kVector},
    {"line[].weight[]", "drag_area", Kind::kVector},
};

// The table at `path` (made when missing; an entry of an array of tables chosen at random, or
// added 1 time in 4), or null when something of another type is in the way.
toml::table* FindOrMakeTable(Rng& rng, toml::table& root, std::string_view path) {
  toml::table* t = &root;
  while (!path.empty()) {
    const std::size_t dot = path.find('.');
    std::string_view part = path.substr(0, dot);
    path = dot == std::string_view::npos ? std::string_view() : path.substr(dot + 1);
    const bool entry = part.size() > 2 && part.substr(part.size() - 2) == "[]";
    if (entry) part.remove_suffix(2);
    const std::string name(part);
    toml::node* n = t->get(name);
    if (entry) {
      if (!n) n = t->insert_or_assign(name, toml::array{}).first->second.as_array();
      toml::array* a = n ? n->as_array() : nullptr;
      if (!a) return nullptr;
      if (!a->empty() && !IsTableArray(*a)) return nullptr;
      if (a->empty() || OneIn(rng, 4)) a->push_back(toml::table{});
      t = a->get(Pick(rng, a->size()))->as_table();
    } else {
      if (!n) n = &t->insert_or_assign(name, toml::table{}).first->second;
      t = n->as_table();
      if (!t) return nullptr;
    }
  }
  return t;
}

bool AddKnownKey(Rng& rng, Doc& doc, toml::table& root) {
  const KnownKey& k = kKnownKeys[Pick(rng, std::size(kKnownKeys))];
  toml::table* t = FindOrMakeTable(rng, root, k.table);
  if (!t) return false;
  Slot s;
  s.table = t;
  s.key = k.key;
  if (OneIn(rng, 8)) {
    SetOtherType(rng, s, doc);
    return true;
  }
  switch (k.kind) {
    case Kind::kNumber:
      if (std::string_view(k.key) == "time_step" && OneIn(rng, 3))
        Set(s, std::string("auto"));
      else
        Set(s, SomeDouble(rng));
      break;
    case Kind::kInteger:
      Set(s, OneIn(rng, 2) ? static_cast<std::int64_t>(1 + Pick(rng, 100))
                           : HostileInteger(rng, 10));
      break;
    case Kind::kString: {
      std::string v = SomeString(rng, k.key, doc);
      // A line's ends and a section's material name what is there, mostly.
      const std::string key = k.key;
      if ((key == "start" || key == "end" || key == "material") && !doc.strings.empty() &&
          !OneIn(rng, 4))
        v = doc.strings[Pick(rng, doc.strings.size())];
      Set(s, v);
      break;
    }
    case Kind::kVector: {
      toml::array a;
      const std::size_t n = 2 + Pick(rng, 2);
      for (std::size_t i = 0; i < n; ++i) a.push_back(SomeDouble(rng));
      Set(s, std::move(a));
      break;
    }
    case Kind::kBool:
      Set(s, OneIn(rng, 2));
      break;
    case Kind::kCurrent:
      switch (Pick(rng, 3)) {
        case 0: Set(s, SomeDouble(rng)); break;
        case 1: Set(s, toml::array{SomeDouble(rng), SomeDouble(rng)}); break;
        default: {
          toml::array profile;
          const std::size_t n = 1 + Pick(rng, 4);
          for (std::size_t i = 0; i < n; ++i)
            profile.push_back(toml::array{-10.0 * static_cast<double>(i), SomeDouble(rng)});
          Set(s, std::move(profile));
        }
      }
      break;
  }
  return true;
}

bool ChangeLineEnd(Rng& rng, Doc& doc) {
  std::vector<std::string> points;
  std::vector<toml::table*> lines;
  for (auto& [a, path] : doc.table_arrays) {
    if (path != "point" && path != "line") continue;
    for (toml::node& n : *a) {
      toml::table& t = *n.as_table();
      if (path == "line") {
        lines.push_back(&t);
      } else if (const toml::node* name = t.get("name")) {
        if (const toml::value<std::string>* v = name->as_string()) points.push_back(v->get());
      }
    }
  }
  if (lines.empty() || points.empty()) return false;
  toml::table& line = *lines[Pick(rng, lines.size())];
  line.insert_or_assign(OneIn(rng, 2) ? "start" : "end", points[Pick(rng, points.size())]);
  return true;
}

bool WrongType(Rng& rng, Doc& doc) {
  if (doc.slots.empty()) return false;
  SetOtherType(rng, doc.slots[Pick(rng, doc.slots.size())], doc);
  return true;
}

bool ResizeArray(Rng& rng, Doc& doc) {
  std::vector<const Slot*> arrays;
  for (const Slot& s : doc.slots)
    if (const toml::array* a = s.node->as_array())
      if (!IsTableArray(*a)) arrays.push_back(&s);
  if (arrays.empty()) return false;
  toml::array& a = *arrays[Pick(rng, arrays.size())]->node->as_array();
  switch (Pick(rng, 4)) {
    case 0:
      if (a.empty()) return false;
      a.pop_back();
      break;
    case 1:
      a.clear();
      break;
    case 2:
      if (a.empty()) return false;
      a.push_back(*a.get(Pick(rng, a.size())));
      break;
    default:
      a.push_back(HostileDouble(rng, 1.0));
      break;
  }
  return true;
}

bool MutateOnce(Rng& rng, toml::table& root) {
  Doc doc;
  WalkTable(root, "", doc);
  // Weights: numbers most, they are most of a scene.
  const std::size_t r = Pick(rng, 100);
  if (r < 32) return MutateNumber(rng, doc);
  if (r < 40) return MutateString(rng, doc);
  if (r < 48) return DeleteKey(rng, doc);
  if (r < 54) return DuplicateEntry(rng, doc);
  if (r < 58) return DeleteEntry(rng, doc);
  if (r < 64) return CopyKey(rng, doc);
  if (r < 80) return AddKnownKey(rng, doc, root);
  if (r < 86) return ChangeLineEnd(rng, doc);
  if (r < 93) return WrongType(rng, doc);
  return ResizeArray(rng, doc);
}

// The scene's text and the motion table after it (from "# ---- motion.csv ----", or empty).
void Split(const std::string& input, std::string* scene, std::string* table) {
  const std::size_t cut = input.find(kTableSeparator);
  if (cut == std::string::npos) {
    *scene = input;
    table->clear();
  } else {
    *scene = input.substr(0, cut + 1);
    *table = input.substr(cut + 1);
  }
}

bool Parse(const std::string& text, toml::table* root) {
  try {
    *root = toml::parse(text);
  } catch (const toml::parse_error&) {
    return false;
  }
  return true;
}

std::string Write(const toml::table& root, const std::string& table) {
  std::ostringstream os;
  os << root;
  std::string text = os.str();
  if (!table.empty()) {
    if (text.empty() || text.back() != '\n') text += '\n';
    text += table;
  }
  return text;
}

std::size_t Output(const std::string& text, std::uint8_t* data, std::size_t max_size) {
  if (text.empty() || text.size() > max_size) return 0;
  std::memcpy(data, text.data(), text.size());
  return text.size();
}

}  // namespace

extern "C" std::size_t LLVMFuzzerCustomMutator(std::uint8_t* data, std::size_t size,
                                                std::size_t max_size, unsigned int seed) {
  Rng rng(seed);
  const std::string input(reinterpret_cast<const char*>(data), size);
  std::string scene, table;
  Split(input, &scene, &table);
  toml::table root;
  if (OneIn(rng, 64) || !Parse(scene, &root)) return LLVMFuzzerMutate(data, size, max_size);
  if (!table.empty() && OneIn(rng, 10)) {
    // The motion table alone, byte by byte (a CSV); the scene as it is.
    std::string t = table;
    const std::size_t room = max_size > scene.size() ? max_size - scene.size() : 0;
    if (room <= t.size()) return LLVMFuzzerMutate(data, size, max_size);
    t.resize(room);
    const std::size_t n = LLVMFuzzerMutate(reinterpret_cast<std::uint8_t*>(t.data()),
                                           table.size(), room);
    t.resize(n);
    if (t.compare(0, std::strlen(kTableSeparator) - 1, kTableSeparator + 1) != 0)
      t = std::string(kTableSeparator + 1) + t;  // the separator stays
    const std::size_t out = Output(scene + t, data, max_size);
    return out ? out : LLVMFuzzerMutate(data, size, max_size);
  }
  for (int attempt = 0; attempt < 8; ++attempt) {
    toml::table copy = root;
    if (!MutateOnce(rng, copy)) continue;
    const std::size_t out = Output(Write(copy, table), data, max_size);
    if (out) return out;
  }
  return LLVMFuzzerMutate(data, size, max_size);
}

extern "C" std::size_t LLVMFuzzerCustomCrossOver(const std::uint8_t* data1, std::size_t size1,
                                                  const std::uint8_t* data2, std::size_t size2,
                                                  std::uint8_t* out, std::size_t max_out_size,
                                                  unsigned int seed) {
  Rng rng(seed);
  std::string scene1, table1, scene2, table2;
  Split(std::string(reinterpret_cast<const char*>(data1), size1), &scene1, &table1);
  Split(std::string(reinterpret_cast<const char*>(data2), size2), &scene2, &table2);
  toml::table root1, root2;
  if (!Parse(scene1, &root1) || !Parse(scene2, &root2) || root2.empty()) return 0;
  auto it = root2.begin();
  std::advance(it, static_cast<std::ptrdiff_t>(Pick(rng, root2.size())));
  const std::string key(it->first.str());
  toml::array* into = root1.get_as<toml::array>(key);
  const toml::array* from = it->second.as_array();
  if (into && from && IsTableArray(*into) && IsTableArray(*from) && !OneIn(rng, 4)) {
    // One entry of the other's [[key]], added to this one's.
    into->insert(into->cbegin() + static_cast<std::ptrdiff_t>(Pick(rng, into->size() + 1)),
                 *from->get(Pick(rng, from->size())));
  } else {
    root1.insert_or_assign(key, it->second);
  }
  return Output(Write(root1, table1.empty() ? table2 : table1), out, max_out_size);
}
