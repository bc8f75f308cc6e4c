// Every key the scene loader accepts is documented in docs/scene-format.md (issue 18): the
// loader's schema is run over scenes that hold every one of its tables and every kind of end
// motion, with the keys it asks for collected (scene/key_log.h); each must appear in the
// manual in backticks by its full dotted name (`environment.current`, `cable.section.length`,
// `ends.end.x_rao`, `title`).
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include "scene/scene_parser.h"

namespace cablefilm {
namespace {

std::string Read(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string Replace(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

// Case P63 with every optional table, and its far end moved each way the loader knows.
std::vector<std::string> ScenesWithEveryKey() {
  const std::string src = CABLEFILM_SOURCE_DIR;
  const std::string p63 = Read(src + "/scenes/polachek1963.toml");
  const std::string tables =
      "\n[seabed]\ny = -10.0\n\n[waves]\nheight = 1.0\nperiod = 8.0\nsurface_y = 40.0\n"
      "\n[film]\nwidth = 640\nheight = 360\n";
  const std::string trochoid_end =
      "motion = \"trochoid\"\nx_amplitudes = [1.8288, 0.0]\ny_amplitudes = [0.0, 1.8288]\n"
      "period = 10.0\nramp_rate = 0.5";
  std::vector<std::string> scenes;
  for (const std::string& motion :
       {trochoid_end, std::string("motion = \"fixed\""), std::string("motion = \"free\""),
        std::string("motion = \"wave\"\nx_rao = [1.0, 90.0]\ny_rao = [1.0, 0.0]"),
        "motion = \"table\"\nfile = \"" + src + "/scenes/ship_motion.csv\""})
    scenes.push_back(Replace(p63, trochoid_end, motion) + tables);
  // A system of lines (issue 20), with a free point's every key and a line's weight.
  scenes.push_back(Read(src + "/scenes/spread_mooring.toml") +
                   "\n[[point]]\nname = \"buoy\"\nmotion = \"free\"\nposition = [0.0, -5.0, 0.0]\n"
                   "mass = 100.0\nvolume = 1.0\nadded_volume = [0.5, 0.5]\nforce = [1e3, 0.0, 0.0]\n"
                   "\n[[line]]\nname = \"riser\"\nmodel = \"elastic\"\nstart = \"buoy\"\n"
                   "end = \"fairlead1\"\n[[line.section]]\nmaterial = \"chain\"\nlength = 20.0\n"
                   "segments = 4\n[[line.weight]]\nat = 10.0\nmass = 50.0\n");
  // Driven bodies that turn (issue 20): a trochoid's angles, a wave's angle RAOs.
  const std::string spread = Read(src + "/scenes/spread_mooring.toml");
  scenes.push_back(spread +
                   "\n[[body]]\nname = \"ship\"\nmotion = \"trochoid\"\nposition = [0.0, 0.0, 0.0]\n"
                   "x_amplitudes = [1.0, 0.0]\nrx_amplitudes = [1.0, 0.0]\n"
                   "ry_amplitudes = [0.0, 2.0]\nrz_amplitudes = [0.5, 0.5]\nperiod = 10.0\n"
                   "ramp_rate = 0.5\n");
  scenes.push_back(spread + "\n[waves]\nheight = 1.0\nperiod = 8.0\nsurface_y = 0.0\n"
                   "\n[[body]]\nname = \"ship\"\nmotion = \"wave\"\nposition = [0.0, 0.0, 0.0]\n"
                   "x_rao = [1.0, 90.0]\nrx_rao = [2.0, 0.0]\nry_rao = [1.0, 10.0]\n"
                   "rz_rao = [3.0, -90.0]\n");
  return scenes;
}

TEST(SceneKeys, EveryKeyTheLoaderAcceptsIsInTheManual) {
  KeyLog keys;
  for (const std::string& scene : ScenesWithEveryKey())
    ASSERT_NO_THROW(ParseScene(scene, CABLEFILM_SOURCE_DIR "/scenes/every_key.toml", &keys));
  // The schema's tables and keys: a few dozen. Fewer would mean the scenes missed a table.
  EXPECT_GT(keys.size(), 60u);
  const std::string manual = Read(CABLEFILM_SOURCE_DIR "/docs/scene-format.md");
  ASSERT_FALSE(manual.empty()) << "docs/scene-format.md is missing";
  std::string missing;
  for (const std::string& key : keys)
    if (manual.find("`" + key + "`") == std::string::npos) missing += " " + key;
  EXPECT_TRUE(missing.empty()) << "not documented in docs/scene-format.md:" << missing;
  // And the check itself: a key the schema does not know is not taken for documented.
  EXPECT_EQ(keys.count("environment.current"), 1u);
  EXPECT_EQ(keys.count("cable.section.length"), 1u);
  EXPECT_EQ(keys.count("ends.end.x_rao"), 1u);
  EXPECT_EQ(keys.count("body.rz_amplitudes"), 1u);
  EXPECT_EQ(keys.count("body.ry_rao"), 1u);
  EXPECT_EQ(manual.find("`environment.no_such_key`"), std::string::npos);
}

}  // namespace
}  // namespace cablefilm
