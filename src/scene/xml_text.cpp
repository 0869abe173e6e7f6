#include "xml_text.h"

namespace rt {

using tinyxml2::XMLElement;

std::string describe(const XMLElement* e) {
  std::string s = e->Name();
  if (const char* id = e->Attribute("id")) s += " id=" + shorten(id);
  return s;
}

std::string path_of(const XMLElement* e) {
  std::string s = describe(e);
  for (auto* p = e->Parent() ? e->Parent()->ToElement() : nullptr; p;
       p = p->Parent() ? p->Parent()->ToElement() : nullptr) {
    if (std::string(p->Name()) == "Scene") break;
    s = describe(p) + " > " + s;
  }
  return s;
}

std::string text_of(const XMLElement* e) {
  std::string s;
  for (auto* n = e->FirstChild(); n; n = n->NextSibling())
    if (const auto* t = n->ToText()) s += t->Value();
  return s;
}

std::string shorten(const std::string& in, size_t max_chars) {
  std::string v;
  for (char ch : in) {
    const unsigned char c = static_cast<unsigned char>(ch);
    if (c == ' ' || (c >= '\t' && c <= '\r')) {
      if (!v.empty() && v.back() != ' ') v += ' ';
    } else {
      // Bytes beyond ASCII are replaced too: a message must not carry arbitrary binary.
      v += c < 32 || c >= 127 ? '?' : ch;
    }
  }
  if (!v.empty() && v.back() == ' ') v.pop_back();
  if (v.size() > max_chars) v = v.substr(0, max_chars > 3 ? max_chars - 3 : 0) + "...";
  return v;
}

std::string shorten(const char* in) { return shorten(std::string(in ? in : "")); }

}  // namespace rt
