// Turns the scene template (scenes/handover_scene.xml) into the MJCF text
// that is compiled, with the object and the person sized from SimOptions.
// The template stays a valid scene on its own: the builder rewrites
// attributes of elements found by their `name`, and never touches others.
// Not real-time: used once at load.
#pragma once

#include <string>

#include "scenes/sim/sim_options.hpp"

namespace handover::sim {

/// Sets attribute `attr` of the single element whose name="element_name"
/// (replacing the value or adding the attribute). Returns false if no element
/// has that name. `xml` is MJCF text; comments are skipped.
bool setElementAttribute(std::string& xml, const std::string& element_name,
                         const std::string& attr, const std::string& value);

/// The template with the object's geom (type, size, mass, friction), its
/// resting position on the table, and the person's geoms (legs, torso, head,
/// upper arm, forearm) rewritten from `options`. `source_name` is only used in
/// error messages. Throws handover::InputError naming the file and the element
/// when the template lacks one of the named elements the builder needs.
std::string buildSceneXml(const std::string& template_text, const SimOptions& options,
                          const std::string& source_name);

}  // namespace handover::sim
