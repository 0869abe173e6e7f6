#include "util/args.h"

#include "util/spelling.h"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace rt {
namespace {

// Help lines: two spaces, the option and its value, help from this column, this wide.
constexpr size_t kHelpColumn = 25;
constexpr size_t kHelpWidth = 90;

std::string label(const OptionInfo& o) {
  std::string s;
  for (const std::string& n : o.names) s += (s.empty() ? "" : ", ") + n;
  return o.takes_value() ? s + " " + o.metavar : s;
}

std::string sentence(const OptionInfo& o) {
  if (o.default_text.empty()) return o.help;
  return o.help + " (default " + o.default_text + ")";
}

// Wraps `text` into lines of at most kHelpWidth, each indented to kHelpColumn, the first
// after `head` (which is padded to the column or gets a line of its own when too long).
std::string wrapped(const std::string& head, const std::string& text) {
  std::string out = head;
  if (out.size() + 1 > kHelpColumn)
    out += "\n" + std::string(kHelpColumn, ' ');
  else
    out += std::string(kHelpColumn - out.size(), ' ');
  size_t col = kHelpColumn;
  std::istringstream words(text);
  bool first = true;
  for (std::string w; words >> w; first = false) {
    if (!first && col + 1 + w.size() > kHelpWidth) {
      out += "\n" + std::string(kHelpColumn, ' ');
      col = kHelpColumn;
    } else if (!first) {
      out += ' ';
      ++col;
    }
    out += w;
    col += w.size();
  }
  return out + "\n";
}

std::string section_title(const OptionInfo& o) {
  return o.reach == Reach::kDevice ? o.section + " (reaches the device)" : o.section;
}

// Table cells: a bar would end the cell and angle brackets would read as HTML.
std::string markdown_cell(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '|')
      out += "\\|";
    else if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else
      out += c;
  }
  return out;
}

std::string format_bound(double v, bool whole) {
  if (whole) return std::to_string(static_cast<long long>(v));
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

}  // namespace

bool Range::contains(double v) const {
  return (lo_open ? v > lo : v >= lo) && (hi_open ? v < hi : v <= hi);
}

std::string Range::describe(bool whole) const {
  if (!whole && lo == 0 && lo_open && hi >= 1e12) return "a positive number";
  return std::string(whole ? "a whole number" : "a number") + " in " + (lo_open ? "(" : "[") +
         format_bound(lo, whole) + ", " + format_bound(hi, whole) + (hi_open ? ")" : "]");
}

long parse_whole(const std::string& value, const Range& range) {
  char* end = nullptr;
  errno = 0;
  long v = std::strtol(value.c_str(), &end, 10);
  if (value.empty() || *end || errno == ERANGE || !range.contains(static_cast<double>(v)))
    throw UsageError("is not " + range.describe(true));
  return v;
}

double parse_number(const std::string& value, const Range& range) {
  char* end = nullptr;
  double v = std::strtod(value.c_str(), &end);
  if (value.empty() || *end) throw UsageError("is not " + range.describe(false));
  // "a positive number" leaves the upper end unsaid: a value beyond it gets it named.
  if (v > 0 && v >= range.hi && !range.contains(v) &&
      range.describe(false).find(format_bound(range.hi, false)) == std::string::npos)
    throw UsageError("is too large: the limit is " + format_bound(range.hi, false));
  if (!std::isfinite(v) || !range.contains(v)) throw UsageError("is not " + range.describe(false));
  return v;
}

std::vector<std::string> split_commas(const std::string& value) {
  std::vector<std::string> out;
  std::stringstream ss(value);
  for (std::string item; std::getline(ss, item, ',');) out.push_back(item);
  return out;
}

std::string OptionText::help() const {
  std::string out = "usage: " + synopsis_ + "\n\n" + description_ + "\n";
  std::string section = "\x01";  // No section title equals this.
  for (const OptionInfo& o : infos_) {
    if (section_title(o) != section) {
      section = section_title(o);
      out += "\n" + (section.empty() ? std::string("Options") : section) + ":\n";
    }
    out += wrapped("  " + label(o), sentence(o));
  }
  if (!env_.empty()) {
    out += "\nEnvironment:\n";
    for (const EnvVar& e : env_) out += wrapped("  " + e.name, e.help);
  }
  out += "\n  --help, --help-markdown" + std::string(version_.empty() ? "" : ", --version") + "\n";
  return out;
}

std::string OptionText::section_help(const std::string& section) const {
  std::string out;
  for (const OptionInfo& o : infos_)
    if (o.section == section) out += wrapped("  " + label(o), sentence(o));
  return out;
}

std::string OptionText::markdown() const {
  std::string out = "| option | default | reaches | meaning |\n|---|---|---|---|\n";
  for (const OptionInfo& o : infos_) {
    std::string def = o.default_text.empty() ? "" : "`" + markdown_cell(o.default_text) + "`";
    out += "| `" + markdown_cell(label(o)) + "` | " + def + " | " +
           (o.reach == Reach::kDevice ? "device" : "host") + " | " + markdown_cell(o.help) + " |\n";
  }
  if (!env_.empty()) {
    out += "\n| environment variable | meaning |\n|---|---|\n";
    for (const EnvVar& e : env_) out += "| `" + e.name + "` | " + markdown_cell(e.help) + " |\n";
  }
  return out;
}

void OptionText::usage_error(const std::string& what) const {
  std::fprintf(stderr, "%s: %s (see %s --help)\n", program_.c_str(), what.c_str(),
               program_.c_str());
  std::exit(2);
}

std::string OptionText::suggest(const std::string& typed) const {
  std::vector<std::string> names;
  for (const OptionInfo& o : infos_)
    for (const std::string& n : o.names) names.push_back(n);
  std::string near = closest_name(typed, names);
  if (!near.empty()) return near;
  // Then by what it does: the first word of each option's help ("samples per pixel" is
  // --spp), for a name typed from the meaning ("--sammples").
  std::vector<std::string> words;
  for (const OptionInfo& o : infos_) {
    std::string w;
    for (char c : o.help) {
      if (!std::isalpha(static_cast<unsigned char>(c))) break;
      w += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
    words.push_back(w.size() >= 4 ? w : "");
  }
  const std::string bare = typed.substr(typed.find_first_not_of('-') == std::string::npos
                                            ? typed.size()
                                            : typed.find_first_not_of('-'));
  near = bare.size() >= 4 ? closest_name(bare, words) : "";
  for (size_t k = 0; k < words.size() && !near.empty(); ++k)
    if (words[k] == near) return infos_[k].names[0];
  return "";
}

std::vector<std::string> OptionText::walk(
    int argc, char** argv, int first, const std::function<void(size_t, const std::string*)>& apply,
    std::string* exit_text) const {
  std::vector<std::string> positional;
  for (int i = first; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--help" || a == "-h") {
      *exit_text = help();
      return positional;
    }
    if (a == "--help-markdown") {
      *exit_text = markdown();
      return positional;
    }
    if (a == "--version" && !version_.empty()) {
      *exit_text = program_ + " " + version_ + "\n";
      return positional;
    }
    std::string name = a, value;
    size_t eq = a.find('=');
    bool inline_value = a.rfind("--", 0) == 0 && eq != std::string::npos;
    if (inline_value) {
      name = a.substr(0, eq);
      value = a.substr(eq + 1);
    }
    size_t found = infos_.size();
    for (size_t k = 0; k < infos_.size() && found == infos_.size(); ++k)
      for (const std::string& n : infos_[k].names)
        if (n == name) found = k;
    if (found == infos_.size()) {
      if (a.size() > 1 && a[0] == '-') {
        const std::string near = suggest(name);
        throw UsageError("unknown option '" + a + "'" +
                         (near.empty() ? "" : "; did you mean " + near + "?"));
      }
      positional.push_back(a);
      continue;
    }
    if (!infos_[found].takes_value()) {
      if (inline_value) throw UsageError(name + " takes no value");
      apply(found, nullptr);
      continue;
    }
    if (!inline_value) {
      if (i + 1 >= argc) throw UsageError(name + " needs a value");
      value = argv[++i];
    }
    try {
      apply(found, &value);
    } catch (const UsageError& e) {
      throw UsageError(name + ": '" + value + "' " + e.what());
    }
  }
  return positional;
}

}  // namespace rt
