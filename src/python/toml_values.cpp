#include "python/toml_values.h"

#include <cmath>
#include <memory>
#include <sstream>
#include <vector>
#include <toml++/toml.h>

namespace py = pybind11;

namespace cablefilm::python {
namespace {

[[noreturn]] void Unwritable(const py::handle& value, const std::string& key) {
  throw py::type_error(key + ": a " + std::string(py::str(py::type::of(value).attr("__name__"))) +
                       " cannot be written in a scene (expected a number, a string, true or "
                       "false, a list or a dict)");
}

void MakeInline(toml::node& node) {
  if (toml::table* t = node.as_table()) {
    t->is_inline(true);
    for (auto&& [k, v] : *t) MakeInline(v);
  } else if (toml::array* a = node.as_array()) {
    for (toml::node& v : *a) MakeInline(v);
  }
}

// Values nested deeper than this (dicts, lists, tuples and tolist() results within each other)
// are refused: a scene nests a handful, TOML parsers stop at a few hundred, and the conversion
// recurses once a level on the C stack, which a list nested 100 000 deep overflowed.
constexpr int kMaxNesting = 64;

// The containers from the root to the value being converted: a value that contains itself
// (d["environment"]["loop"] = d) is found by its identity, as json.dumps finds it.
struct Path {
  std::vector<const PyObject*> open;
};

// Enters `obj` (one level deeper) for the life of the guard: a ValueError when it is one of the
// containers it is inside, or when it is one level too deep.
class Enter {
 public:
  Enter(Path& path, const py::handle& obj, const std::string& key) : path_(path) {
    for (const PyObject* outer : path.open)
      if (outer == obj.ptr())
        throw py::value_error(Name(key) + ": the value contains itself (a circular reference); "
                              "expected a tree of dicts and lists");
    if (static_cast<int>(path.open.size()) >= kMaxNesting)
      throw py::value_error(Name(key) + ": nested more than " + std::to_string(kMaxNesting) +
                            " levels deep (dicts, lists and tolist() values within each "
                            "other); expected a scene's few levels");
    path.open.push_back(obj.ptr());
  }
  ~Enter() { path_.open.pop_back(); }
  Enter(const Enter&) = delete;
  Enter& operator=(const Enter&) = delete;

 private:
  static std::string Name(const std::string& key) { return key.empty() ? "the scene" : key; }
  Path& path_;
};

// A str as UTF-8: a lone surrogate ("\ud800") has none, and TOML holds only Unicode text
// (pybind11's cast would raise a RuntimeError "Unable to cast Python instance to C++ type").
std::string Utf8(const py::handle& s, const std::string& what) {
  try {
    return s.cast<std::string>();
  } catch (const py::cast_error&) {
    throw py::value_error(what + ": a string that is not valid Unicode (a lone surrogate), " +
                          "which TOML cannot hold");
  }
}

// The TOML value of `obj`: a table, an array, a bool, an integer, a float or a string.
std::unique_ptr<toml::node> ToNode(const py::handle& obj, const std::string& key, Path& path);

toml::table ToTable(const py::handle& obj, const std::string& key, Path& path) {
  const Enter inside(path, obj, key);
  toml::table table;
  for (const auto& item : py::reinterpret_borrow<py::dict>(obj)) {
    if (!py::isinstance<py::str>(item.first))
      throw py::type_error(key + ": a dict's keys must be strings, got a " +
                           std::string(py::str(py::type::of(item.first).attr("__name__"))));
    const std::string name =
        Utf8(item.first, key.empty() ? std::string("a key of the scene") : "a key of " + key);
    table.insert_or_assign(name,
                           *ToNode(item.second, key.empty() ? name : key + "." + name, path));
  }
  return table;
}

std::unique_ptr<toml::node> ToNode(const py::handle& obj, const std::string& key, Path& path) {
  if (py::isinstance<py::bool_>(obj)) return std::make_unique<toml::value<bool>>(obj.cast<bool>());
  if (py::isinstance<py::str>(obj))
    return std::make_unique<toml::value<std::string>>(Utf8(obj, key));
  if (py::isinstance<py::dict>(obj)) return std::make_unique<toml::table>(ToTable(obj, key, path));
  if (py::hasattr(obj, "tolist") && !py::isinstance<py::list>(obj) &&
      !py::isinstance<py::tuple>(obj)) {
    // A numpy array or scalar: its Python values (a scalar's tolist() is the scalar). A level
    // of its own: an object whose tolist() gives another such object ends at kMaxNesting.
    const Enter inside(path, obj, key);
    const py::object plain = obj.attr("tolist")();
    if (!plain.is(obj)) return ToNode(plain, key, path);
  }
  if (py::isinstance<py::list>(obj) || py::isinstance<py::tuple>(obj)) {
    const Enter inside(path, obj, key);
    auto array = std::make_unique<toml::array>();
    std::size_t i = 0;
    for (const py::handle item : obj)
      array->push_back(*ToNode(item, key + "[" + std::to_string(i++) + "]", path));
    return array;
  }
  if (py::isinstance<py::int_>(obj)) {
    try {
      return std::make_unique<toml::value<std::int64_t>>(obj.cast<std::int64_t>());
    } catch (const py::cast_error&) {
      throw py::value_error(key + ": the integer " + std::string(py::str(obj)) +
                            " is beyond TOML's 64-bit integers");
    }
  }
  if (py::isinstance<py::float_>(obj))
    return std::make_unique<toml::value<double>>(obj.cast<double>());
  Unwritable(obj, key);
}

py::object ToPython(const toml::node& node) {
  if (const toml::table* t = node.as_table()) {
    py::dict d;
    for (auto&& [k, v] : *t) d[py::str(std::string(k.str()))] = ToPython(v);
    return std::move(d);
  }
  if (const toml::array* a = node.as_array()) {
    py::list l;
    for (const toml::node& v : *a) l.append(ToPython(v));
    return std::move(l);
  }
  if (const auto* s = node.as_string()) return py::str(s->get());
  if (const auto* i = node.as_integer()) return py::int_(i->get());
  if (const auto* f = node.as_floating_point()) return py::float_(f->get());
  if (const auto* b = node.as_boolean()) return py::bool_(b->get());
  std::ostringstream os;  // a date or a time: its TOML text
  node.visit([&](auto&& v) { os << v; });
  return py::str(os.str());
}

}  // namespace

std::string DictToToml(const py::dict& scene) {
  Path path;
  std::ostringstream os;
  os << ToTable(scene, "", path) << "\n";
  return os.str();
}

std::string ValueToToml(const py::handle& value, const std::string& key) {
  Path path;
  toml::table holder;
  holder.insert_or_assign("v", *ToNode(value, key, path));
  MakeInline(*holder.get("v"));
  std::ostringstream os;
  os << holder;
  std::string text = os.str();
  const std::string lead = "v = ";
  if (text.compare(0, lead.size(), lead) == 0) text.erase(0, lead.size());
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
  return text;
}

py::object TomlDocumentValue(const std::string& document) {
  const toml::table t = toml::parse(document);
  return ToPython(*t.get("v"));
}

py::dict TomlToDict(const std::string& text) {
  const toml::table t = toml::parse(text);
  return py::reinterpret_steal<py::dict>(ToPython(t).release());
}

}  // namespace cablefilm::python
