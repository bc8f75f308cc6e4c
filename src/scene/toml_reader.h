#pragma once
// A scene file's TOML read key by key: each key's value checked against what it must be, every
// problem an Error "file:line: key: expected ...", and every key of a table left unread at the
// end an "unknown key" (a typo is never silently ignored). The scene's schema (scene_parser.h)
// is written on it.
#include <cmath>
#include <array>
#include <cstdint>
#include <set>
#include <sstream>
#include <string>
#include <toml++/toml.h>
#include <vector>

#include "core/error.h"
#include "scene/key_log.h"
#include "scene/scene_limits.h"
#include "scene/text_escape.h"

namespace cablefilm {

// The text as a TOML table; not TOML: an Error "file:line: not valid TOML: ...".
toml::table ParseToml(const std::string& text, const std::string& file);

// The largest integer a double holds exactly, and every integer below it: 2^53.
constexpr std::int64_t kMaxExactInteger = std::int64_t{1} << 53;

// Reads the keys of one TOML table, remembering which were read, so that Finish() can report
// every key left over as unknown. Errors carry "file:line: key: expected ...".
class TableReader {
 public:
  // The file's top-level table; `keys` (optional) collects every key asked for.
  TableReader(const toml::table& root, const std::string& file, KeyLog* keys = nullptr)
      : table_(root), file_(EscapeText(file)), keys_(keys) {}

 private:
  TableReader(const toml::table& table, const std::string& escaped_file, KeyLog* keys, bool)
      : table_(table), file_(escaped_file), keys_(keys) {}

 public:
  // A table within: `prefix` is its full name as messages show it (cable.section[1]).
  TableReader Child(const toml::table& table, std::string prefix) const {
    TableReader r(table, file_, keys_, true);
    r.prefix_ = std::move(prefix);
    return r;
  }

  // The key's full name as a message shows it (a quoted TOML key may hold any character).
  std::string Key(const std::string& key) const {
    return EscapeText(prefix_.empty() ? key : prefix_ + "." + key);
  }
  [[noreturn]] void Fail(const toml::node* node, const std::string& key,
                         const std::string& expected) const {
    const auto& src = node ? node->source() : table_.source();
    std::ostringstream os;
    os << file_ << ":" << src.begin.line << ": " << Key(key) << ": " << expected;
    throw Error(os.str());
  }
  const toml::node* Get(const std::string& key) {
    used_.insert(key);
    if (keys_) keys_->insert(LoggedKey(key));
    return table_.get(key);
  }
  bool Has(const std::string& key) const { return table_.contains(key); }

  double Number(const std::string& key, const toml::node* n, const std::string& what) const {
    if (!n->is_number()) Fail(n, key, "expected " + what);
    if (n->is_integer()) {
      // toml++ gives no double for an integer beyond 2^53 (it has no exact one).
      const std::int64_t i = n->as_integer()->get();
      if (i > kMaxExactInteger || i < -kMaxExactInteger)
        Fail(n, key, "expected " + what + ", got the integer " + std::to_string(i) +
                         ", beyond 2^53 (" + std::to_string(kMaxExactInteger) +
                         ") where no decimal number is exact");
      return static_cast<double>(i);
    }
    const double v = n->as_floating_point()->get();
    if (!std::isfinite(v)) Fail(n, key, "expected " + what + ", got a non-finite number");
    return v;
  }
  // Checks a number read against [lo, hi]; `what` already states the range.
  double InRange(const std::string& key, double v, double lo, double hi,
                 const std::string& what) const {
    if (!(v >= lo && v <= hi)) Fail(table_.get(key), key, "expected " + what + ", got " + Fmt(v));
    return v;
  }
  // A number from lo to hi (both included); fallback when absent and not required.
  double Ranged(const std::string& key, double fallback, bool required, double lo, double hi,
                const std::string& unit) {
    const std::string what = "a number" + unit + " from " + Fmt(lo) + " to " + Fmt(hi);
    const toml::node* n = Get(key);
    if (!n) {
      if (required) Fail(nullptr, key, "missing; expected " + what);
      return fallback;
    }
    return InRange(key, Number(key, n, what), lo, hi, what);
  }
  // what: the expectation in words, e.g. "a positive length in m".
  double Required(const std::string& key, const std::string& what) {
    const toml::node* n = Get(key);
    if (!n) Fail(nullptr, key, "missing; expected " + what);
    return Number(key, n, what);
  }
  double Optional(const std::string& key, double fallback, const std::string& what) {
    const toml::node* n = Get(key);
    return n ? Number(key, n, what) : fallback;
  }
  // A positive number at most `hi`, and at least `lo` when lo > 0 (lo = 0: any above 0).
  double Positive(const std::string& key, const std::string& unit, double lo, double hi) {
    const std::string what = "a positive number" + unit +
                             (lo > 0 ? " from " + Fmt(lo) + " to " + Fmt(hi)
                                     : ", at most " + Fmt(hi));
    const double v = Required(key, what);
    if (!(v > 0 && v >= lo && v <= hi))
      Fail(table_.get(key), key, "expected " + what + ", got " + Fmt(v));
    return v;
  }
  double OptionalPositive(const std::string& key, double fallback, const std::string& unit,
                          double lo, double hi) {
    if (!Has(key)) {
      Get(key);
      return fallback;
    }
    return Positive(key, unit, lo, hi);
  }
  double OptionalNonNegative(const std::string& key, double fallback, const std::string& unit,
                             double hi) {
    const std::string what = "a number >= 0" + unit + ", at most " + Fmt(hi);
    const double v = Optional(key, fallback, what);
    if (!(v >= 0 && v <= hi)) Fail(table_.get(key), key, "expected " + what + ", got " + Fmt(v));
    return v;
  }
  int Integer(const std::string& key, int fallback, int min, int max, bool required) {
    const toml::node* n = Get(key);
    const std::string what = "a whole number from " + std::to_string(min) + " to " +
                             std::to_string(max);
    if (!n) {
      if (required) Fail(nullptr, key, "missing; expected " + what);
      return fallback;
    }
    if (!n->is_integer()) Fail(n, key, "expected " + what);
    const int64_t v = n->value<int64_t>().value();
    if (v < min || v > max) Fail(n, key, "expected " + what + ", got " + std::to_string(v));
    return static_cast<int>(v);
  }
  // Two numbers each within [0, limit] (non_negative) or [-limit, limit].
  std::array<double, 2> Pair(const std::string& key, std::array<double, 2> fallback,
                             bool required, bool non_negative, const std::string& unit,
                             double limit) {
    const toml::node* n = Get(key);
    const std::string what = std::string("an array of two ") +
                             (non_negative ? "numbers >= 0" : "numbers") + unit + " from " +
                             (non_negative ? "0" : Fmt(-limit)) + " to " + Fmt(limit);
    if (!n) {
      if (required) Fail(nullptr, key, "missing; expected " + what);
      return fallback;
    }
    const toml::array* a = n->as_array();
    if (!a || a->size() != 2) Fail(n, key, "expected " + what);
    std::array<double, 2> out{};
    for (size_t i = 0; i < 2; ++i) {
      out[i] = Number(key, a->get(i), what);
      if (!(out[i] >= (non_negative ? 0.0 : -limit) && out[i] <= limit))
        Fail(n, key, "expected " + what + ", got " + Fmt(out[i]));
    }
    return out;
  }
  // How two numbers are read where three may be: [x, y] is [x, y, 0] (a position in the plane)
  // or [x, y, x] (a property the same across both horizontal axes).
  enum class TwoValues { kZeroZ, kZLikeX };
  // Two or three numbers each within [0, limit] (non_negative) or [-limit, limit].
  std::array<double, 3> Triple(const std::string& key, std::array<double, 3> fallback,
                               bool required, bool non_negative, const std::string& unit,
                               double limit, TwoValues two) {
    const toml::node* n = Get(key);
    const std::string what = std::string("an array of two or three ") +
                             (non_negative ? "numbers >= 0" : "numbers") + unit + " from " +
                             (non_negative ? "0" : Fmt(-limit)) + " to " + Fmt(limit);
    if (!n) {
      if (required) Fail(nullptr, key, "missing; expected " + what);
      return fallback;
    }
    const toml::array* a = n->as_array();
    if (!a || (a->size() != 2 && a->size() != 3)) Fail(n, key, "expected " + what);
    std::array<double, 3> out{};
    for (size_t i = 0; i < a->size(); ++i) {
      out[i] = Number(key, a->get(i), what);
      if (!(out[i] >= (non_negative ? 0.0 : -limit) && out[i] <= limit))
        Fail(n, key, "expected " + what + ", got " + Fmt(out[i]));
    }
    if (a->size() == 2) out[2] = two == TwoValues::kZLikeX ? out[0] : 0.0;
    return out;
  }
  std::string String(const std::string& key, const std::string& fallback, bool required) {
    const toml::node* n = Get(key);
    if (!n) {
      if (required) Fail(nullptr, key, "missing; expected a string");
      return fallback;
    }
    if (!n->is_string()) Fail(n, key, "expected a string");
    return n->value<std::string>().value();
  }
  std::string Choice(const std::string& key, const std::string& fallback,
                     const std::vector<std::string>& choices) {
    std::string list;
    for (const auto& c : choices) list += (list.empty() ? "" : ", ") + QuoteText(c);
    const toml::node* n = Get(key);
    if (!n) return fallback;
    if (!n->is_string()) Fail(n, key, "expected one of " + list);
    const std::string v = n->value<std::string>().value();
    for (const auto& c : choices)
      if (v == c) return v;
    Fail(n, key, "expected one of " + list + ", got " + QuoteText(v));
  }
  bool Bool(const std::string& key, bool fallback) {
    const toml::node* n = Get(key);
    if (!n) return fallback;
    if (!n->is_boolean()) Fail(n, key, "expected true or false");
    return n->value<bool>().value();
  }
  const toml::table* SubTable(const std::string& key, bool required) {
    const toml::node* n = Get(key);
    if (!n) {
      if (required) Fail(nullptr, key, "missing; expected a table [" + Key(key) + "]");
      return nullptr;
    }
    if (!n->is_table()) Fail(n, key, "expected a table [" + Key(key) + "]");
    return n->as_table();
  }
  const toml::array* TableArray(const std::string& key, bool required) {
    const toml::node* n = Get(key);
    if (!n) {
      if (required) Fail(nullptr, key, "missing; expected one or more [[" + Key(key) + "]]");
      return nullptr;
    }
    const toml::array* a = n->as_array();
    if (!a || !a->is_array_of_tables())
      Fail(n, key, "expected an array of tables [[" + Key(key) + "]]");
    return a;
  }
  // Every key present but never read is a mistake; `hint` says why some keys may be unused.
  void Finish(const std::string& hint = "") const {
    for (auto&& [k, node] : table_) {
      const std::string key(k.str());
      if (used_.count(key)) continue;
      std::ostringstream os;
      os << file_ << ":" << k.source().begin.line << ": " << Key(key) << ": unknown key"
         << hint;
      throw Error(os.str());
    }
  }
  static std::string Fmt(double v) { return FormatNumber(v); }

 private:
  // The key's dotted name without indices: cable.section[1] + length -> cable.section.length.
  std::string LoggedKey(const std::string& key) const {
    std::string name;
    bool in_index = false;
    for (char c : prefix_.empty() ? key : prefix_ + "." + key) {
      if (c == '[') in_index = true;
      if (!in_index) name += c;
      if (c == ']') in_index = false;
    }
    return name;
  }

  const toml::table& table_;
  std::string prefix_;
  std::string file_;  // escaped, for messages
  KeyLog* keys_ = nullptr;
  std::set<std::string> used_;
};

}  // namespace cablefilm
