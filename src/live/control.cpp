#include "live/control.h"

#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>

namespace cablefilm {
namespace {

using Json = nlohmann::json;

// The value as the message shows it: scalars and short flat arrays as JSON (ASCII, escaped),
// anything nested only by its kind and size: dumping it would recurse as deep as it nests.
std::string Shown(const Json& v) {
  bool flat = v.is_primitive() || (v.is_array() && v.size() <= 4);
  if (v.is_array())
    for (const Json& e : v) flat = flat && e.is_primitive();
  if (!flat)
    return v.is_array() ? "an array of " + std::to_string(v.size()) + " elements"
                        : "an object with " + std::to_string(v.size()) + " fields";
  std::string s = v.dump(-1, ' ', true, Json::error_handler_t::replace);
  if (s.size() > 60) s = s.substr(0, 57) + "...";
  return s;
}

std::string Number(double v) {
  std::ostringstream o;
  o << v;
  return o.str();
}

bool ReadBool(const Json& v, const char* field) {
  if (!v.is_boolean())
    throw ControlError(std::string(field) + ": expected true or false, got " + Shown(v));
  return v.get<bool>();
}

double ReadNumber(const Json& v, const char* field, double lo, double hi, const char* unit) {
  const std::string want = std::string(field) + ": expected a number in [" + Number(lo) + ", " +
                           Number(hi) + "]" + unit;
  if (!v.is_number()) throw ControlError(want + ", got " + Shown(v));
  const double x = v.get<double>();
  if (!std::isfinite(x)) throw ControlError(want + ", got a non-finite number");
  if (x < lo || x > hi) throw ControlError(want + ", got " + Number(x));
  return x;
}

// "reset", or an object of finite numbers; their ranges are the camera's to clamp to (a drag
// that overshoots still turns the view as far as it goes).
CameraRequest ReadCamera(const Json& v) {
  const std::string want =
      "camera: expected \"reset\" or an object with any of azimuth, elevation (degrees) and "
      "zoom (a finite number each)";
  CameraRequest c;
  if (v.is_string() && v.get<std::string>() == "reset") {
    c.reset = true;
    return c;
  }
  if (!v.is_object() || v.empty()) throw ControlError(want + ", got " + Shown(v));
  for (auto it = v.begin(); it != v.end(); ++it) {
    const Json& x = it.value();
    std::optional<double>* field = it.key() == "azimuth"     ? &c.azimuth
                                   : it.key() == "elevation" ? &c.elevation
                                   : it.key() == "zoom"      ? &c.zoom
                                                             : nullptr;
    if (!field) throw ControlError(want + ", got the field " + Shown(Json(it.key())));
    if (!x.is_number() || !std::isfinite(x.get<double>()))
      throw ControlError("camera." + it.key() + ": expected a finite number, got " + Shown(x));
    *field = x.get<double>();
  }
  return c;
}

}  // namespace

const std::vector<std::string>& ControlFields() {
  static const std::vector<std::string> fields{
      "pause", "step", "restart", "speed", "amplitude_scale", "period",
      "current", "current_heading", "wave_height", "wave_period", "wave_heading", "offset_x",
      "offset_z", "force_x", "force_z", "colormap", "lock_range", "reset_range",
      "tension_range", "record", "camera"};
  return fields;
}

bool ControlRequest::empty() const {
  return !pause && !step && !restart && !speed && !amplitude_scale && !period && !current &&
         !current_heading && !wave_height && !wave_period && !wave_heading && !colormap &&
         !lock_range && !reset_range && !tension_range && !record && !camera && !offset_x &&
         !offset_z && !force_x && !force_z;
}

ControlRequest ParseControl(const std::string& body, const ControlLimits& limits) {
  if (body.size() > kMaxControlBytes)
    throw ControlError("control: expected a JSON object of at most " +
                       std::to_string(kMaxControlBytes) + " bytes, got " +
                       std::to_string(body.size()));
  // No exceptions from the parser: a bad body is an answer, not an error of the server. The
  // depth of nesting is bounded by the size limit above.
  const Json j = Json::parse(body, nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded()) throw ControlError("control: malformed JSON (expected an object such as {\"pause\": true})");
  if (!j.is_object()) throw ControlError("control: expected a JSON object, got " + Shown(j));
  ControlRequest r;
  for (auto it = j.begin(); it != j.end(); ++it) {
    const std::string& key = it.key();
    const Json& v = it.value();
    if (key == "pause") {
      r.pause = ReadBool(v, "pause");
    } else if (key == "step") {
      if (!v.is_boolean() || !v.get<bool>())
        throw ControlError("step: expected true, got " + Shown(v));
      r.step = true;
    } else if (key == "restart") {
      if (!v.is_boolean() || !v.get<bool>())
        throw ControlError("restart: expected true, got " + Shown(v));
      r.restart = true;
    } else if (key == "speed") {
      r.speed = ReadNumber(v, "speed", limits.speed_min, limits.speed_max,
                           " (simulated seconds per second)");
    } else if (key == "amplitude_scale" || key == "period") {
      if (!limits.has_driven_end)
        throw ControlError(key + ": the scene has no driven end (an end or a point with motion "
                           "= \"trochoid\", \"table\" or \"wave\")");
      if (key == "period")
        r.period = ReadNumber(v, "period", limits.period_min, limits.period_max, " s");
      else
        r.amplitude_scale = ReadNumber(v, "amplitude_scale", 0, limits.amplitude_max,
                                       " (times the scene's amplitudes)");
    } else if (key == "current") {
      if (limits.current_history)
        throw ControlError("current: the current follows the scene's environment.current_file");
      r.current = ReadNumber(v, "current", -limits.current_max, limits.current_max, " m/s");
    } else if (key == "current_heading") {
      if (limits.current_history)
        throw ControlError("current_heading: the current follows the scene's "
                           "environment.current_file");
      r.current_heading = ReadNumber(v, "current_heading", -limits.heading_max,
                                     limits.heading_max, " degrees from +x towards +z");
    } else if (key == "wave_height") {
      if (!limits.has_waves) throw ControlError("wave_height: the scene has no [waves]");
      r.wave_height = ReadNumber(v, "wave_height", 0, limits.wave_height_max,
                                 " m (crest to trough, at most the breaking height)");
    } else if (key == "wave_period") {
      if (!limits.has_waves) throw ControlError("wave_period: the scene has no [waves]");
      if (limits.irregular_sea)
        throw ControlError("wave_period: an irregular sea's periods are its spectrum's; its "
                           "height (Hs) can change");
      r.wave_period = ReadNumber(v, "wave_period", limits.wave_period_min,
                                 limits.wave_period_max, " s");
    } else if (key == "wave_heading") {
      if (!limits.has_waves) throw ControlError("wave_heading: the scene has no [waves]");
      if (limits.irregular_sea)
        throw ControlError("wave_heading: an irregular sea's directions are its spectrum's; its "
                           "height (Hs) can change");
      r.wave_heading = ReadNumber(v, "wave_heading", -limits.heading_max, limits.heading_max,
                                  " degrees from +x towards +z (the way the waves travel)");
    } else if (key == "offset_x" || key == "offset_z") {
      if (!limits.has_vessel)
        throw ControlError(key + ": the scene has no vessel to move (no end or point with a "
                           "motion, no driven or held body; a free body goes where its loads "
                           "put it)");
      (key == "offset_x" ? r.offset_x : r.offset_z) =
          ReadNumber(v, key.c_str(), -limits.offset_max, limits.offset_max,
                     " m (the vessel's offset from the scene's position)");
    } else if (key == "force_x" || key == "force_z") {
      if (!limits.has_free_body)
        throw ControlError(key + ": the scene has no free body to push (offset_x and offset_z "
                           "move a vessel that the scene moves)");
      (key == "force_x" ? r.force_x : r.force_z) =
          ReadNumber(v, key.c_str(), -limits.force_max, limits.force_max,
                     " N (an extra steady force on the free bodies)");
    } else if (key == "colormap") {
      std::string names;
      for (const std::string& n : limits.colormaps) names += (names.empty() ? "" : ", ") + n;
      if (!v.is_string()) throw ControlError("colormap: expected one of " + names + ", got " + Shown(v));
      const std::string name = v.get<std::string>();
      bool known = false;
      for (const std::string& n : limits.colormaps) known = known || n == name;
      if (!known) throw ControlError("colormap: expected one of " + names + ", got " + Shown(v));
      r.colormap = name;
    } else if (key == "lock_range") {
      r.lock_range = ReadBool(v, "lock_range");
    } else if (key == "reset_range") {
      if (!v.is_boolean() || !v.get<bool>())
        throw ControlError("reset_range: expected true, got " + Shown(v));
      r.reset_range = true;
    } else if (key == "tension_range") {
      const std::string want = "tension_range: expected [min, max] in N with 0 <= min < max <= " +
                               Number(limits.tension_max);
      if (!v.is_array() || v.size() != 2 || !v[0].is_number() || !v[1].is_number())
        throw ControlError(want + ", got " + Shown(v));
      const double lo = v[0].get<double>(), hi = v[1].get<double>();
      if (!std::isfinite(lo) || !std::isfinite(hi) || !(lo >= 0) || !(hi > lo) ||
          hi > limits.tension_max)
        throw ControlError(want + ", got " + Shown(v));
      r.tension_range = std::array<double, 2>{lo, hi};
    } else if (key == "record") {
      r.record = ReadBool(v, "record");
    } else if (key == "camera") {
      if (!limits.space)
        throw ControlError("camera: the scene is drawn in the plane (start with --view 3d to "
                           "draw it in space)");
      r.camera = ReadCamera(v);
    } else {
      std::string names;
      for (const std::string& n : ControlFields()) names += (names.empty() ? "" : ", ") + n;
      throw ControlError("unknown field " + Shown(Json(key)) + "; expected any of " + names);
    }
  }
  return r;
}

}  // namespace cablefilm
