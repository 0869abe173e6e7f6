#include "scene/xml_diagnosis.h"

#include <cctype>
#include <cstring>
#include <utility>
#include <vector>

#include "scene/xml_text.h"

namespace rt {

std::string non_xml_kind(const std::string& bytes) {
  auto starts = [&](const char* magic, size_t n) {
    return bytes.size() >= n && std::memcmp(bytes.data(), magic, n) == 0;
  };
  if (starts("ply\n", 4) || starts("ply\r\n", 5)) return "PLY";
  if (starts("\x89PNG\r\n\x1a\n", 8)) return "PNG";
  if (starts("\xff\xd8\xff", 3)) return "JPEG";
  if (starts("\x76\x2f\x31\x01", 4)) return "OpenEXR";
  if (starts("#?RADIANCE", 10) || starts("#?RGBE", 6)) return "Radiance HDR";
  return "";
}

namespace {

bool name_start(char c) {
  const unsigned char u = static_cast<unsigned char>(c);
  return std::isalpha(u) || c == '_' || c == ':' || u >= 0x80;
}
bool name_char(char c) {
  return name_start(c) || std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '.';
}

class Scan {
 public:
  explicit Scan(const std::string& t) : t_(t) {}

  XmlProblem run() {
    while (p_ < t_.size()) {
      if (t_[p_] == '<') {
        if (!markup()) return problem_;
      } else if (t_[p_] == '&') {
        if (!entity()) return problem_;
      } else {
        advance(1);
      }
    }
    if (!open_.empty())
      return fail(line_, "the element <" + open_.back().first + "> opened at line " +
                             std::to_string(open_.back().second) + " is never closed");
    return {};
  }

 private:
  void advance(size_t n) {
    for (size_t i = 0; i < n && p_ < t_.size(); ++i) line_ += t_[p_++] == '\n';
  }
  bool at(const char* s) const { return t_.compare(p_, std::strlen(s), s) == 0; }
  XmlProblem fail(int line, const std::string& what) {
    problem_ = {line, what};
    return problem_;
  }
  // Skips to past `end`; false (with the sentence) when the file ends first.
  bool skip_to(const char* end, const char* what) {
    const int start = line_;
    const size_t e = t_.find(end, p_);
    if (e == std::string::npos) {
      fail(start, std::string("the ") + what + " opened at line " + std::to_string(start) +
                      " is never closed with '" + end + "'");
      return false;
    }
    advance(e + std::strlen(end) - p_);
    return true;
  }
  std::string name() {
    const size_t b = p_;
    while (p_ < t_.size() && name_char(t_[p_])) ++p_;
    return t_.substr(b, p_ - b);
  }
  void spaces() {
    while (p_ < t_.size() && std::isspace(static_cast<unsigned char>(t_[p_]))) advance(1);
  }

  bool entity() {
    const int line = line_;
    const size_t semi = t_.find(';', p_);
    std::string ref = semi == std::string::npos ? "" : t_.substr(p_ + 1, semi - p_ - 1);
    bool ok = ref == "amp" || ref == "lt" || ref == "gt" || ref == "quot" || ref == "apos";
    if (!ok && ref.size() > 1 && ref[0] == '#') {
      const bool hex = ref[1] == 'x';
      ok = ref.size() > (hex ? 2u : 1u);
      for (size_t i = hex ? 2 : 1; i < ref.size(); ++i)
        ok = ok && (hex ? std::isxdigit(static_cast<unsigned char>(ref[i]))
                        : std::isdigit(static_cast<unsigned char>(ref[i])));
    }
    if (!ok) {
      fail(line, "'&' does not start an entity such as &amp; (write &amp; for a literal '&')");
      return false;
    }
    advance(semi + 1 - p_);
    return true;
  }

  bool markup() {
    const int line = line_;
    if (at("<!--")) return skip_to("-->", "comment");
    if (at("<![CDATA[")) return skip_to("]]>", "CDATA section");
    if (at("<?")) return skip_to("?>", "declaration");
    if (at("<!")) return skip_to(">", "declaration");
    advance(1);
    if (p_ < t_.size() && t_[p_] == '/') {
      advance(1);
      const std::string n = name();
      spaces();
      if (n.empty() || p_ >= t_.size() || t_[p_] != '>') {
        fail(line, "the closing tag </" + shorten(n) + " is not ended by '>'");
        return false;
      }
      advance(1);
      if (open_.empty()) {
        fail(line, "</" + shorten(n) + "> closes no open element");
        return false;
      }
      if (open_.back().first != n) {
        const auto& [inner, opened] = open_.back();
        bool deeper = false;
        for (const auto& o : open_) deeper = deeper || o.first == n;
        fail(line, deeper
                       ? "the element <" + shorten(inner) + "> opened at line " +
                             std::to_string(opened) + " is not closed before </" + shorten(n) + ">"
                       : "</" + shorten(n) + "> does not match the open element <" +
                             shorten(inner) + "> (line " + std::to_string(opened) + ")");
        return false;
      }
      open_.pop_back();
      return true;
    }
    if (p_ >= t_.size() || !name_start(t_[p_])) {
      fail(line, "'<' does not start an element (write &lt; for a literal '<')");
      return false;
    }
    const std::string n = name();
    for (;;) {
      spaces();
      if (p_ >= t_.size()) {
        fail(line, "the tag <" + shorten(n) + " at line " + std::to_string(line) +
                       " is not ended by '>'");
        return false;
      }
      if (at("/>")) {
        advance(2);
        return true;
      }
      if (t_[p_] == '>') {
        advance(1);
        open_.push_back({n, line});
        return true;
      }
      const std::string a = name();
      spaces();
      if (a.empty() || p_ >= t_.size() || t_[p_] != '=') {
        fail(line_, a.empty() ? "unexpected '" + shorten(t_.substr(p_, 1)) + "' in the tag <" +
                                    shorten(n) + "> at line " + std::to_string(line)
                              : "the attribute " + shorten(a) + " of <" + shorten(n) +
                                    "> at line " + std::to_string(line) + " has no value");
        return false;
      }
      advance(1);
      spaces();
      const char q = p_ < t_.size() ? t_[p_] : '\0';
      if (q != '"' && q != '\'') {
        fail(line_, "the value of the attribute " + shorten(a) + " of <" + shorten(n) +
                        "> at line " + std::to_string(line) + " is not in quotes");
        return false;
      }
      const size_t close = t_.find(q, p_ + 1);
      const size_t lt = t_.find('<', p_ + 1);
      if (close == std::string::npos || lt < close) {
        fail(line_, "the value of the attribute " + shorten(a) + " of <" + shorten(n) +
                        "> at line " + std::to_string(line) + " has no closing quote");
        return false;
      }
      advance(close + 1 - p_);
    }
  }

  const std::string& t_;
  size_t p_ = 0;
  int line_ = 1;
  std::vector<std::pair<std::string, int>> open_;  // Open elements and their lines.
  XmlProblem problem_;
};

}  // namespace

XmlProblem find_xml_problem(const std::string& text) { return Scan(text).run(); }

}  // namespace rt
