// How messages name a scene key: as it is in a scene file, by the row and column its value came
// from in a MoorDyn file (the file's author never wrote the scene's keys).
#include <gtest/gtest.h>

#include <string>

#include "scene/key_source.h"
#include "scene/scene_def.h"

namespace cablefilm {
namespace {

const KeySources kSources{
    {"material[0]", {6, "LINE TYPES row 1"}},
    {"material[0].youngs_modulus", {6, "LINE TYPES row 1, column EA"}},
    {"point[1].position", {11, "POINTS row 2, columns X, Y, Z"}},
    {"line[0]", {15, "LINES row 1"}}};

TEST(KeySource, SceneFileKeysAreNamedAsTheyAre) {
  SceneDef scene;
  scene.path = "dir/p63.toml";
  EXPECT_EQ(KeyName(scene, "material[0].youngs_modulus"), "material[0].youngs_modulus");
  EXPECT_EQ(KeyPlace(scene, "material[0].youngs_modulus"),
            "dir/p63.toml: material[0].youngs_modulus");
}

TEST(KeySource, MoorDynKeysAreNamedByTheirRowAndColumn) {
  SceneDef scene;
  scene.path = "sys\n.txt";  // escaped, as every name from outside
  scene.sources = kSources;
  EXPECT_EQ(KeyName(scene, "material[0].youngs_modulus"), "LINE TYPES row 1, column EA");
  EXPECT_EQ(KeyName(scene, "line[0]"), "LINES row 1");
  EXPECT_EQ(KeyPlace(scene, "point[1].position"), "sys\\n.txt:11: POINTS row 2, columns X, Y, Z");
  // A key the file gave no value for (the conversion's own): the key.
  EXPECT_EQ(KeyPlace(scene, "simulation.time_step"), "sys\\n.txt: simulation.time_step");
}

TEST(KeySource, LoadersMessagesAreToldAtTheFilesRow) {
  EXPECT_EQ(MoorDynKeyMessage("sys.txt:21: material[0].youngs_modulus: expected 1 to 1e13",
                              "sys.txt", kSources),
            "sys.txt:6: LINE TYPES row 1, column EA (the scene's material[0].youngs_modulus): "
            "expected 1 to 1e13");
  // An element of a value, a key of a table with no source of its own: the nearest one's.
  EXPECT_EQ(MoorDynKeyMessage("sys.txt:30: point[1].position[2]: expected x", "sys.txt", kSources),
            "sys.txt:11: POINTS row 2, columns X, Y, Z (the scene's point[1].position[2]): "
            "expected x");
  EXPECT_EQ(MoorDynKeyMessage("sys.txt:22: material[0].drag_coefficient: expected x", "sys.txt",
                              kSources),
            "sys.txt:6: LINE TYPES row 1 (the scene's material[0].drag_coefficient): expected x");
  // Nothing to tell: no key of the file's, another file, no line, no key.
  EXPECT_EQ(MoorDynKeyMessage("sys.txt:3: seabed.y: expected x", "sys.txt", kSources), "");
  EXPECT_EQ(MoorDynKeyMessage("sys.txt:3: material[0]x: expected x", "sys.txt", kSources), "");
  EXPECT_EQ(MoorDynKeyMessage("a.txt:21: material[0].youngs_modulus: x", "sys.txt", kSources), "");
  EXPECT_EQ(MoorDynKeyMessage("sys.txt: material[0].youngs_modulus: x", "sys.txt", kSources), "");
  EXPECT_EQ(MoorDynKeyMessage("sys.txt:4: not valid TOML", "sys.txt", kSources), "");
}

}  // namespace
}  // namespace cablefilm
