// Helpers that turn parts of an XML scene file into text for one-line messages.
#pragma once

#include <tinyxml2.h>

#include <string>

namespace rt {

// "Material id=3": the element's name and id.
std::string describe(const tinyxml2::XMLElement* e);

// The element's path below <Scene>: "Objects > Mesh id=2 > Faces".
std::string path_of(const tinyxml2::XMLElement* e);

// All the element's text, also where comments split it (<Gaze>0 0 <!-- z --> -1</Gaze>);
// tinyxml2's GetText() would return only the first piece.
std::string text_of(const tinyxml2::XMLElement* e);

// Makes text from an input file fit a one-line message: whitespace runs become one space,
// other unprintable bytes '?', and anything past max_chars is cut with "...".
std::string shorten(const std::string& in, size_t max_chars = 40);
std::string shorten(const char* in);

}  // namespace rt
