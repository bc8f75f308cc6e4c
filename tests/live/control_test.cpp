// Parsing and validation of the live view's controls: every field accepted in range, and every
// way of being wrong refused with a message naming the field and what was expected.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "live/control.h"
#include "view/camera.h"

namespace cablefilm {
namespace {

ControlLimits Limits() {
  ControlLimits l;
  l.period_min = 1;
  l.period_max = 100;
  l.current_max = 3;
  l.colormaps = {"viridis", "cividis", "magma"};
  return l;
}

std::string Refusal(const std::string& body, const ControlLimits& limits = Limits()) {
  try {
    ParseControl(body, limits);
  } catch (const ControlError& e) {
    return e.what();
  }
  return "(accepted)";
}

TEST(ParseControl, AcceptsEveryFieldInRange) {
  const ControlRequest r = ParseControl(
      R"({"pause": true, "step": true, "restart": true, "speed": 2.5, "amplitude_scale": 1.5,
          "period": 12, "current": -0.5, "colormap": "magma", "lock_range": false,
          "tension_range": [0, 9000], "record": true})",
      Limits());
  EXPECT_EQ(r.pause, true);
  EXPECT_TRUE(r.step);
  EXPECT_TRUE(r.restart);
  EXPECT_DOUBLE_EQ(*r.speed, 2.5);
  EXPECT_DOUBLE_EQ(*r.amplitude_scale, 1.5);
  EXPECT_DOUBLE_EQ(*r.period, 12);
  EXPECT_DOUBLE_EQ(*r.current, -0.5);
  EXPECT_EQ(*r.colormap, "magma");
  EXPECT_EQ(r.lock_range, false);
  EXPECT_DOUBLE_EQ((*r.tension_range)[1], 9000);
  EXPECT_EQ(r.record, true);
  EXPECT_TRUE(ParseControl("{}", Limits()).empty());
  // The ends of every range are inside it.
  EXPECT_NO_THROW(ParseControl(R"({"speed": 0.1, "amplitude_scale": 0, "period": 100, "current": 3})", Limits()));
  EXPECT_NO_THROW(ParseControl(R"({"speed": 10, "amplitude_scale": 3, "period": 1, "current": -3})", Limits()));
}

TEST(ParseControl, MalformedOrNotAnObject) {
  EXPECT_EQ(Refusal("{\"pause\": tru"), "control: malformed JSON (expected an object such as {\"pause\": true})");
  EXPECT_EQ(Refusal(""), "control: malformed JSON (expected an object such as {\"pause\": true})");
  EXPECT_EQ(Refusal("{\"speed\": 1} trailing"), "control: malformed JSON (expected an object such as {\"pause\": true})");
  EXPECT_EQ(Refusal("[1, 2]"), "control: expected a JSON object, got [1,2]");
  EXPECT_EQ(Refusal("\"pause\""), "control: expected a JSON object, got \"pause\"");
  EXPECT_EQ(Refusal(std::string(5000, ' ') + "{}"),
            "control: expected a JSON object of at most 4096 bytes, got 5002");
  // Invalid UTF-8 is malformed JSON, never echoed raw.
  EXPECT_EQ(Refusal("{\"colormap\": \"\xff\xfe\"}"),
            "control: malformed JSON (expected an object such as {\"pause\": true})");
}

// Found by fuzzing the server: a deeply nested body was dumped into the message recursively
// and overflowed the stack of the server's thread. Nested values are now described, not shown.
TEST(ParseControl, DeepNestingIsDescribedNotDumped) {
  const std::string deep = std::string(2000, '[') + std::string(2000, ']');
  EXPECT_EQ(Refusal(deep), "control: expected a JSON object, got an array of 1 elements");
  EXPECT_EQ(Refusal("{\"speed\": " + deep + "}"),
            "speed: expected a number in [0.1, 10] (simulated seconds per second), got an array "
            "of 1 elements");
  EXPECT_EQ(Refusal(R"({"pause": {"a": 1}})"), "pause: expected true or false, got an object with 1 fields");
}

TEST(ParseControl, UnknownFieldIsNamedAndEscaped) {
  EXPECT_EQ(Refusal(R"({"speed": 1, "sped": 2})"),
            "unknown field \"sped\"; expected any of pause, step, restart, speed, amplitude_scale, "
            "period, current, current_heading, wave_height, wave_period, wave_heading, offset_x, "
            "offset_z, force_x, force_z, colormap, lock_range, reset_range, tension_range, "
            "record, camera");
  // A control character in a key comes back escaped, not raw to a terminal or page.
  EXPECT_EQ(Refusal("{\"a\\u001bb\": 1}").substr(0, 25), "unknown field \"a\\u001bb\";");
}

// The 3D view's camera: any finite numbers, clamped by the session (ClampCamera); anything
// else refused whole, naming the field; and only for a scene drawn in space.
TEST(ParseControl, CameraTakesFiniteNumbersOrReset) {
  ControlLimits space = Limits();
  space.space = true;
  const ControlRequest r =
      ParseControl(R"({"camera": {"azimuth": 1e308, "elevation": -1e300, "zoom": 0}})", space);
  ASSERT_TRUE(r.camera);
  OrbitCamera c;
  c.azimuth = *r.camera->azimuth;
  c.elevation = *r.camera->elevation;
  c.zoom = *r.camera->zoom;
  const OrbitCamera clamped = ClampCamera(c);
  EXPECT_TRUE(std::isfinite(clamped.azimuth));
  EXPECT_GT(clamped.azimuth, -180);
  EXPECT_LE(clamped.azimuth, 180);
  EXPECT_EQ(clamped.elevation, -kMaxElevation);
  EXPECT_EQ(clamped.zoom, kMinZoom);
  OrbitCamera nan;
  nan.azimuth = nan.elevation = nan.zoom = std::numeric_limits<double>::quiet_NaN();
  const OrbitCamera fallback = ClampCamera(nan), defaults;
  EXPECT_EQ(fallback.azimuth, defaults.azimuth);
  EXPECT_EQ(fallback.elevation, defaults.elevation);
  EXPECT_EQ(fallback.zoom, defaults.zoom);
  EXPECT_TRUE(ParseControl(R"({"camera": "reset"})", space).camera->reset);
  EXPECT_EQ(Refusal(R"({"camera": {"zoom": "near"}})", space),
            "camera.zoom: expected a finite number, got \"near\"");
  EXPECT_EQ(Refusal(R"({"camera": {"azimuth": null}})", space),
            "camera.azimuth: expected a finite number, got null");
  for (const char* bad : {R"({"camera": {"roll": 1}})", R"({"camera": {}})", R"({"camera": [1, 2]})",
                          R"({"camera": "spin"})", R"({"camera": true})"})
    EXPECT_EQ(Refusal(bad, space).rfind("camera: expected \"reset\" or an object", 0), 0u) << bad;
  EXPECT_NE(Refusal(R"({"pause": true, "camera": {"zoom": "x"}})", space), "(accepted)");
  // Drawn in the plane: there is no camera to move.
  EXPECT_EQ(Refusal(R"({"camera": "reset"})").rfind("camera: the scene is drawn in the plane", 0), 0u);
}

TEST(ParseControl, ResetRangeTakesTrueOnly) {
  EXPECT_TRUE(ParseControl(R"({"reset_range": true})", Limits()).reset_range);
  EXPECT_FALSE(ParseControl(R"({"reset_range": true})", Limits()).empty());
  EXPECT_EQ(Refusal(R"({"reset_range": false})"), "reset_range: expected true, got false");
  EXPECT_EQ(Refusal(R"({"reset_range": 1})"), "reset_range: expected true, got 1");
}

TEST(ParseControl, WrongTypes) {
  EXPECT_EQ(Refusal(R"({"pause": 1})"), "pause: expected true or false, got 1");
  EXPECT_EQ(Refusal(R"({"pause": "yes"})"), "pause: expected true or false, got \"yes\"");
  EXPECT_EQ(Refusal(R"({"step": false})"), "step: expected true, got false");
  EXPECT_EQ(Refusal(R"({"restart": 1})"), "restart: expected true, got 1");
  EXPECT_EQ(Refusal(R"({"speed": "2"})"),
            "speed: expected a number in [0.1, 10] (simulated seconds per second), got \"2\"");
  EXPECT_EQ(Refusal(R"({"current": null})"), "current: expected a number in [-3, 3] m/s, got null");
  EXPECT_EQ(Refusal(R"({"colormap": 3})"), "colormap: expected one of viridis, cividis, magma, got 3");
  EXPECT_EQ(Refusal(R"({"lock_range": "true"})"), "lock_range: expected true or false, got \"true\"");
  EXPECT_EQ(Refusal(R"({"record": [true]})"), "record: expected true or false, got [true]");
  EXPECT_EQ(Refusal(R"({"tension_range": 5})"),
            "tension_range: expected [min, max] in N with 0 <= min < max <= 1e+09, got 5");
}

TEST(ParseControl, OutOfRangeAndNonFinite) {
  EXPECT_EQ(Refusal(R"({"speed": 50})"),
            "speed: expected a number in [0.1, 10] (simulated seconds per second), got 50");
  EXPECT_EQ(Refusal(R"({"speed": 0.05})"),
            "speed: expected a number in [0.1, 10] (simulated seconds per second), got 0.05");
  EXPECT_EQ(Refusal(R"({"amplitude_scale": -1})"),
            "amplitude_scale: expected a number in [0, 3] (times the scene's amplitudes), got -1");
  EXPECT_EQ(Refusal(R"({"period": 0.5})"), "period: expected a number in [1, 100] s, got 0.5");
  EXPECT_EQ(Refusal(R"({"current": 4})"), "current: expected a number in [-3, 3] m/s, got 4");
  // 1e999 overflows a double: refused as non-finite (or as malformed), never taken as inf.
  const std::string huge = Refusal(R"({"current": 1e999})");
  EXPECT_TRUE(huge == "current: expected a number in [-3, 3] m/s, got a non-finite number" ||
              huge.rfind("control: malformed JSON", 0) == 0)
      << huge;
  EXPECT_EQ(Refusal(R"({"colormap": "jet"})"),
            "colormap: expected one of viridis, cividis, magma, got \"jet\"");
  EXPECT_EQ(Refusal(R"({"tension_range": [9000, 100]})"),
            "tension_range: expected [min, max] in N with 0 <= min < max <= 1e+09, got [9000,100]");
  EXPECT_EQ(Refusal(R"({"tension_range": [-1, 100]})"),
            "tension_range: expected [min, max] in N with 0 <= min < max <= 1e+09, got [-1,100]");
  EXPECT_EQ(Refusal(R"({"tension_range": [0, 1, 2]})"),
            "tension_range: expected [min, max] in N with 0 <= min < max <= 1e+09, got [0,1,2]");
}

TEST(ParseControl, NoDrivenEndRefusesItsControls) {
  ControlLimits l = Limits();
  l.has_driven_end = false;
  const std::string why =
      "the scene has no driven end (an end or a point with motion = \"trochoid\", \"table\" or \"wave\")";
  EXPECT_EQ(Refusal(R"({"amplitude_scale": 1})", l), "amplitude_scale: " + why);
  EXPECT_EQ(Refusal(R"({"period": 10})", l), "period: " + why);
  EXPECT_NO_THROW(ParseControl(R"({"current": 1})", l));
}

// A current over time is its table's: neither its speed nor its heading has a control.
TEST(ParseControl, ACurrentOverTimeRefusesTheCurrentControls) {
  ControlLimits l = Limits();
  EXPECT_NO_THROW(ParseControl(R"({"current": 1, "current_heading": 30})", l));
  l.current_history = true;
  const std::string why = "the current follows the scene's environment.current_file";
  EXPECT_EQ(Refusal(R"({"current": 1})", l), "current: " + why);
  EXPECT_EQ(Refusal(R"({"current_heading": 30})", l), "current_heading: " + why);
}

// The waves' height: only with [waves], from 0 to the scene's breaking height.
TEST(ParseControl, WaveHeightWithinTheBreakingHeight) {
  ControlLimits l = Limits();
  EXPECT_EQ(Refusal(R"({"wave_height": 2})", l), "wave_height: the scene has no [waves]");
  l.has_waves = true;
  l.wave_height_max = 22.3;
  EXPECT_DOUBLE_EQ(*ParseControl(R"({"wave_height": 4.5})", l).wave_height, 4.5);
  EXPECT_FALSE(ParseControl(R"({"wave_height": 0})", l).empty());
  EXPECT_EQ(Refusal(R"({"wave_height": 30})", l),
            "wave_height: expected a number in [0, 22.3] m (crest to trough, at most the "
            "breaking height), got 30");
}

// The waves' period: only with [waves], within the range the session gives.
TEST(ParseControl, WavePeriodWithinItsRange) {
  ControlLimits l = Limits();
  EXPECT_EQ(Refusal(R"({"wave_period": 8})", l), "wave_period: the scene has no [waves]");
  l.has_waves = true;
  l.wave_period_min = 2;
  l.wave_period_max = 18;
  EXPECT_DOUBLE_EQ(*ParseControl(R"({"wave_period": 12.5})", l).wave_period, 12.5);
  EXPECT_EQ(Refusal(R"({"wave_period": 1})", l),
            "wave_period: expected a number in [2, 18] s, got 1");
}

// The current's direction and the waves' (issue 19): degrees from +x towards +z, -360 to 360
// either way as the scene's current_heading and waves.heading; the waves' only with [waves].
TEST(ParseControl, HeadingsInDegreesWithinAFullTurnEitherWay) {
  ControlLimits l = Limits();
  EXPECT_DOUBLE_EQ(*ParseControl(R"({"current_heading": 120})", l).current_heading, 120);
  EXPECT_FALSE(ParseControl(R"({"current_heading": 0})", l).empty());
  EXPECT_DOUBLE_EQ(*ParseControl(R"({"current_heading": -360})", l).current_heading, -360);
  EXPECT_DOUBLE_EQ(*ParseControl(R"({"current_heading": 360})", l).current_heading, 360);
  EXPECT_EQ(Refusal(R"({"current_heading": 361})", l),
            "current_heading: expected a number in [-360, 360] degrees from +x towards +z, got "
            "361");
  EXPECT_EQ(Refusal(R"({"current_heading": -400.5})", l),
            "current_heading: expected a number in [-360, 360] degrees from +x towards +z, got "
            "-400.5");
  EXPECT_EQ(Refusal(R"({"current_heading": "north"})", l),
            "current_heading: expected a number in [-360, 360] degrees from +x towards +z, got "
            "\"north\"");
  EXPECT_EQ(Refusal(R"({"current_heading": null})", l),
            "current_heading: expected a number in [-360, 360] degrees from +x towards +z, got "
            "null");
  const std::string huge = Refusal(R"({"current_heading": 1e999})", l);
  EXPECT_TRUE(huge.rfind("current_heading: expected a number in [-360, 360]", 0) == 0 ||
              huge.rfind("control: malformed JSON", 0) == 0)
      << huge;
  // The waves' heading: refused without waves, whatever its value.
  EXPECT_EQ(Refusal(R"({"wave_heading": 45})", l), "wave_heading: the scene has no [waves]");
  l.has_waves = true;
  l.wave_height_max = 5;
  EXPECT_DOUBLE_EQ(*ParseControl(R"({"wave_heading": -45})", l).wave_heading, -45);
  EXPECT_DOUBLE_EQ(*ParseControl(R"({"wave_heading": 360})", l).wave_heading, 360);
  EXPECT_EQ(Refusal(R"({"wave_heading": 720})", l),
            "wave_heading: expected a number in [-360, 360] degrees from +x towards +z (the way "
            "the waves travel), got 720");
  EXPECT_EQ(Refusal(R"({"wave_heading": [90]})", l),
            "wave_heading: expected a number in [-360, 360] degrees from +x towards +z (the way "
            "the waves travel), got [90]");
  // With the others in one request.
  const ControlRequest r = ParseControl(
      R"({"current": 0.5, "current_heading": 90, "wave_height": 1, "wave_heading": 30})", l);
  EXPECT_DOUBLE_EQ(*r.current, 0.5);
  EXPECT_DOUBLE_EQ(*r.current_heading, 90);
  EXPECT_DOUBLE_EQ(*r.wave_heading, 30);
}

TEST(ParseControl, ARefusalIsWhole) {
  // A bad field after good ones refuses the request: nothing of it is applied by the caller
  // because nothing is returned.
  EXPECT_EQ(Refusal(R"({"pause": true, "speed": 99})"),
            "speed: expected a number in [0.1, 10] (simulated seconds per second), got 99");
}

TEST(ParseControl, EachControlIsOfferedByWhatTheSceneHas) {
  ControlLimits vessel;
  vessel.has_driven_end = false;
  vessel.has_vessel = true;
  vessel.offset_max = 25;
  const ControlRequest r = ParseControl(R"({"offset_x": -6, "offset_z": 2.5})", vessel);
  EXPECT_EQ(*r.offset_x, -6.0);
  EXPECT_EQ(*r.offset_z, 2.5);
  auto refusal = [](const std::string& body, const ControlLimits& l) {
    try {
      ParseControl(body, l);
    } catch (const ControlError& e) {
      return std::string(e.what());
    }
    return std::string("(accepted)");
  };
  EXPECT_EQ(refusal(R"({"offset_x": 26})", vessel),
            "offset_x: expected a number in [-25, 25] m (the vessel's offset from the scene's "
            "position), got 26");
  EXPECT_EQ(refusal(R"({"offset_z": "far"})", vessel).rfind("offset_z: expected a number", 0), 0u);
  EXPECT_EQ(refusal(R"({"amplitude_scale": 1})", vessel).rfind("amplitude_scale: the scene has no driven end", 0), 0u);
  EXPECT_EQ(refusal(R"({"period": 10})", vessel).rfind("period: the scene has no driven end", 0), 0u);
  ControlLimits nothing;  // a driven end alone
  EXPECT_EQ(refusal(R"({"offset_x": 1})", nothing).rfind("offset_x: the scene has no vessel", 0), 0u);
  EXPECT_EQ(refusal(R"({"force_z": 1})", nothing).rfind("force_z: the scene has no free body", 0), 0u);
  EXPECT_NE(refusal(R"({"ofset_x": 1})", vessel).find("offset_x, offset_z, force_x, force_z"),
            std::string::npos);
  EXPECT_EQ(refusal(R"({"force_x": 1})", vessel).rfind("force_x: the scene has no free body", 0), 0u);
  ControlLimits platform = vessel;
  platform.has_vessel = false;
  platform.has_free_body = true;
  platform.force_max = 3e5;
  EXPECT_EQ(*ParseControl(R"({"force_z": -2e5})", platform).force_z, -2e5);
  EXPECT_EQ(refusal(R"({"force_x": 4e5})", platform),
            "force_x: expected a number in [-300000, 300000] N (an extra steady force on the free "
            "bodies), got 400000");
}

}  // namespace
}  // namespace cablefilm
