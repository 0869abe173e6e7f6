// Malformed XML in words. tinyxml2 names its errors by enum (XML_ERROR_PARSING_TEXT) and
// often at the line where it gave up rather than where the mistake is (a missing
// </Scene> is reported at the last element). This reads the text again, keeping the open
// elements with their lines, and says what is wrong and where.
#pragma once

#include <string>

namespace rt {

// "PLY", "PNG", "JPEG", "OpenEXR" or "Radiance HDR" when `bytes` start like such a file
// (given as the scene by mistake); "" otherwise.
std::string non_xml_kind(const std::string& bytes);

struct XmlProblem {
  int line = 0;      // 1-based line the sentence is about.
  std::string what;  // "the element <Scene> opened at line 1 is never closed"
};

// The first mistake in `text` that makes it malformed XML; what is empty when none is
// found (the caller then falls back on the parser's own line).
XmlProblem find_xml_problem(const std::string& text);

}  // namespace rt
