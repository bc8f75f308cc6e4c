#pragma once
// The chain the sea's tests stand in a sea: 550 m of studless chain (115 kg/m) in 40 links from
// an anchor on the bed 100 m down to a fairlead 10 m under the still water 500 m away, which
// follows the waves. Shared by the scene's tests and the runs'.
#include <string>

namespace cablefilm {

// The scene text: `waves` the body of its [waves] table, `fairlead` the fairlead's motion keys
// (x_rao, y_rao, rao_file ...), `duration` [s] the run's, `output` the body of its [output]
// table (film = false always).
inline std::string SeaChainScene(const std::string& waves, const std::string& fairlead,
                                 double duration, const std::string& output = "") {
  return R"(title = "chain in a sea"
[environment]
fluid_density = 1025.0
[seabed]
y = -100.0
[waves]
)" + waves + R"(
[[material]]
name = "chain"
diameter = 0.137
area = 0.01465
mass_per_length = 115.0
youngs_modulus = 3.365e10
[cable]
[[cable.section]]
material = "chain"
length = 550.0
segments = 40
[ends.start]
position = [-500.0, -100.0]
[ends.end]
position = [0.0, -10.0]
motion = "wave"
)" + fairlead + "\n[simulation]\nduration = " + std::to_string(duration) +
         "\n[output]\n" + output + "\nfilm = false\n";
}

}  // namespace cablefilm
