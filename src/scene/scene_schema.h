// The structure of a scene file: which elements and attributes the loader reads, which it
// knows but cannot render yet, how many of each may appear, and whether ids may repeat.
// The table in scene_schema.cpp is the one place that lists them: a feature becomes
// supported by moving its row from kUnsupported to kRead (and teaching the loader to read it).
#pragma once

#include <tinyxml2.h>

#include <string>
#include <vector>

namespace rt {

// Checks the whole document against the table before any value is read:
// - an unsupported element or attribute (one the image would silently lack, such as a
//   texture, a BRDF, a directional light or tone mapping) throws rt::InputError, unless it
//   is empty (the course's older files carry an empty <Textures/>);
// - a repeated single-valued element, or two definitions of the same kind with the same id,
//   throws rt::InputError naming both lines, except where the table lets ids repeat; so do
//   two kinds with one id where a reference could mean either (scene/loader/shared_ids.h);
// - unknown elements and attributes, stray text, a second <Scene> and repeated ids of kinds
//   nothing refers to give one warning per kind, returned in file order; an unknown name
//   near a known one adds "did you mean <Radius>?".
std::vector<std::string> check_scene_structure(const tinyxml2::XMLDocument& doc,
                                               const std::string& file);

// For "missing <Radius>": "; <Radious> at line 5 is not a known element: did you mean
// <Radius>?" when a child of `parent` that no rule knows is a likely misspelling of
// `missing`; "" otherwise.
std::string misspelling_hint(const tinyxml2::XMLElement* parent, const char* missing);

}  // namespace rt
