#include "scene/key_source.h"

#include "scene/scene_def.h"
#include "scene/text_escape.h"

namespace cablefilm {

std::string KeyName(const SceneDef& scene, const std::string& key) {
  const auto it = scene.sources.find(key);
  return it == scene.sources.end() ? key : it->second.place;
}

std::string KeyPlace(const SceneDef& scene, const std::string& key) {
  const std::string file = EscapeText(scene.path);
  const auto it = scene.sources.find(key);
  if (it == scene.sources.end()) return file + ": " + key;
  return file + ":" + std::to_string(it->second.line) + ": " + it->second.place;
}

std::string MoorDynKeyMessage(const std::string& message, const std::string& file,
                              const KeySources& sources) {
  const std::string prefix = EscapeText(file) + ":";
  if (message.compare(0, prefix.size(), prefix) != 0) return "";
  std::size_t at = prefix.size();
  while (at < message.size() && message[at] >= '0' && message[at] <= '9') ++at;
  if (at == prefix.size() || message.compare(at, 2, ": ") != 0) return "";
  const std::string rest = message.substr(at + 2);
  const std::size_t key_end = rest.find(": ");
  if (key_end == std::string::npos) return "";
  const std::string key = rest.substr(0, key_end);
  // The source of the key, or of the nearest table or value it lies within (point[1].position
  // for point[1].position[2]).
  const KeySource* source = nullptr;
  std::size_t matched = 0;
  for (const auto& [name, s] : sources) {
    const bool within = key.compare(0, name.size(), name) == 0 &&
                        (key.size() == name.size() || key[name.size()] == '.' ||
                         key[name.size()] == '[');
    if (within && name.size() >= matched) {
      source = &s;
      matched = name.size();
    }
  }
  if (!source) return "";
  return prefix + std::to_string(source->line) + ": " + source->place + " (the scene's " + key +
         ")" + rest.substr(key_end);
}

}  // namespace cablefilm
