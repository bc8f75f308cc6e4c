#pragma once
// What a viewer of the live view may ask (POST /control, or a text message on /ws): a JSON
// object with any of the fields below. Parsing is strict: malformed JSON, an unknown field, a
// wrong type, a non-finite or out-of-range value is refused whole with a message naming the
// field and what was expected, so a refused request changes nothing.
#include <array>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace cablefilm {

// The ranges a control accepts, from the scene (the driven end's period, its current).
struct ControlLimits {
  double speed_min = 0.1, speed_max = 10;   // simulated seconds per wall second
  double amplitude_max = 3;                 // scale on the scene's end-motion amplitudes
  double period_min = 1, period_max = 100;  // of the driven end [s]
  double current_max = 3;                   // |c| [m/s]
  double heading_max = 360;                 // |heading| [deg], either way, as the scene's
                                            // current_heading and waves.heading
  double tension_max = 1e9;                 // largest colour range end [N]
  bool has_driven_end = true;               // a trochoid or table end: amplitude, period
  bool has_waves = false;                   // [waves]: their height, period and heading
  bool irregular_sea = false;               // an irregular sea: its height (Hs) alone
  bool current_history = false;             // a current over time: the table's, no control
  double wave_height_max = 0;               // the breaking height of the scene's wave [m]
  double wave_period_min = 0, wave_period_max = 0;  // the waves' period range [s]
  std::vector<std::string> colormaps;       // the known colour maps
  bool space = false;                       // drawn in 3D: the camera can be moved
  bool has_vessel = false;                  // points a vessel carries: offset_x, offset_z
  double offset_max = 0;                    // |offset_x|, |offset_z| [m]
  bool has_free_body = false;               // a free body: force_x, force_z
  double force_max = 0;                     // |force_x|, |force_z| [N]
};

// The 3D view's camera as a viewer moves it: any of its fields (each a finite number, clamped
// to its range by the session: view/camera.h), or back to the default.
struct CameraRequest {
  std::optional<double> azimuth, elevation, zoom;  // [deg], [deg], [1]
  bool reset = false;
};

struct ControlRequest {
  std::optional<bool> pause;
  bool step = false;     // advance one frame (pauses first)
  bool restart = false;  // back to the scene's initial state and sea
  std::optional<double> speed, amplitude_scale, period, current;
  std::optional<double> current_heading;             // [deg] from +x towards +z
  std::optional<double> wave_height;                 // H [m], crest to trough
  std::optional<double> wave_period;                 // T [s]
  std::optional<double> wave_heading;                // the way they travel [deg] from +x to +z
  std::optional<double> offset_x, offset_z;          // the vessel's offset [m] (y is up)
  std::optional<double> force_x, force_z;            // on the free bodies [N]
  std::optional<std::string> colormap;
  std::optional<bool> lock_range;                    // freeze the colour range (or let it grow)
  bool reset_range = false;  // unlock the range and start it again from the tensions now
  std::optional<std::array<double, 2>> tension_range;  // [min, max] N: a locked range
  std::optional<bool> record;                        // start (true) or stop (false) a film
  std::optional<CameraRequest> camera;               // {"azimuth", "elevation", "zoom"} or "reset"
  bool empty() const;
};

class ControlError : public std::runtime_error {
 public:
  explicit ControlError(const std::string& what) : std::runtime_error(what) {}
};

constexpr std::size_t kMaxControlBytes = 4096;  // a control is a few fields: refuse floods

// Throws ControlError with the message the viewer gets (HTTP 400).
ControlRequest ParseControl(const std::string& body, const ControlLimits& limits);

// The field names, in the order of the messages.
const std::vector<std::string>& ControlFields();

}  // namespace cablefilm
