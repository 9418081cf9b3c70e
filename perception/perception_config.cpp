#include "perception/perception_config.hpp"

namespace handover::perception {

PerceptionConfig parsePerceptionConfig(const YamlReader& root) {
  PerceptionConfig c;
  if (root.isNull()) return c;
  if (!root.isMap()) root.fail("expected a map of perception settings");
  if (auto v = root.optionalChild("max_gap")) c.max_gap = v->checkRange(v->asDouble(), 1e-3, 10.0);
  if (auto v = root.optionalChild("max_latency")) c.max_latency = v->checkRange(v->asDouble(), 0.0, 10.0);
  if (auto v = root.optionalChild("smoothing_time")) c.smoothing_time = v->checkRange(v->asDouble(), 0.0, 1.0);
  if (auto v = root.optionalChild("rotation_smoothing_time"))
    c.rotation_smoothing_time = v->checkRange(v->asDouble(), 0.0, 1.0);
  if (auto v = root.optionalChild("blend_time")) c.blend_time = v->checkRange(v->asDouble(), 0.0, 5.0);
  root.finish();
  return c;
}

PerceptionConfig loadPerceptionConfig(const std::string& path) {
  return parsePerceptionConfig(YamlReader::loadFile(path));
}

std::string defaultPerceptionConfigPath() { return std::string(HANDOVER_SOURCE_DIR) + "/config/perception.yaml"; }

}  // namespace handover::perception
