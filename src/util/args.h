// One table of command-line options per executable, after pbrt-v4's options.h and
// util/args.h: each option is declared once, with its names, value kind, allowed range or
// choices, default and help line, and from that single declaration come the argv parser,
// the --help text and the Markdown table of the README. Adding an option is one entry in a
// table plus the code that uses its value.
//
// An option writes into a field of the executable's options struct T through an accessor
// (a lambda returning a reference), and the default shown in --help is read back from a
// default-constructed T through the same accessor, so the struct's initializer is the only
// place a default is written.
#pragma once

#include <cstdio>
#include <functional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

// The accessor of a field of the options struct, for the table's entries:
// RT_FIELD(render.spp) reads and writes options.render.spp.
#define RT_FIELD(member) \
  [](auto& options) -> auto& { return options.member; }

namespace rt {

// Where an option's value ends up. Device options reach the renderer's device: the scene
// header both devices read, or the OpenCL program build. Host options stay on the host.
enum class Reach { kHost, kDevice };

// Bad usage: a one-line message, reported as "PROGRAM: MESSAGE (see PROGRAM --help)" with
// exit status 2 by parse_or_exit.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A numeric range; each end open or closed. A value outside it is a usage error.
struct Range {
  double lo = 0, hi = 0;
  bool lo_open = false, hi_open = false;

  static Range closed(double lo, double hi) { return {lo, hi, false, false}; }
  static Range open(double lo, double hi) { return {lo, hi, true, true}; }
  static Range left_open(double lo, double hi) { return {lo, hi, true, false}; }
  // (0, 1e12): any positive number a person would type.
  static Range positive() { return open(0, 1e12); }
  bool contains(double v) const;
  // "a whole number in [1, 4096]", "a positive number", "in (0, 16]".
  std::string describe(bool whole) const;
};

// The parsers every option kind uses; each throws UsageError("is not ...") on a bad value.
long parse_whole(const std::string& value, const Range& range);
double parse_number(const std::string& value, const Range& range);
std::vector<std::string> split_commas(const std::string& value);

// An environment variable the program reads, documented in --help and the README.
struct EnvVar {
  std::string name, help;
};

// What --help and the Markdown table need of an option, whatever T is.
struct OptionInfo {
  std::vector<std::string> names;  // "--quiet", then aliases such as "-q".
  std::string metavar;             // "N", "auto|cl|cpu"; empty for a switch.
  std::string help;                // One sentence; the default is appended.
  std::string default_text;        // Shown as "(default X)"; empty: none shown.
  bool default_in_words = false;   // default_text was written, not read from the defaults.
  std::string section;
  Reach reach = Reach::kHost;
  bool takes_value() const { return !metavar.empty(); }
};

// The type-independent half of a table: texts, formatting and the argv walk.
class OptionText {
 public:
  OptionText(std::string program, std::string synopsis, std::string description)
      : program_(std::move(program)),
        synopsis_(std::move(synopsis)),
        description_(std::move(description)) {}

  const std::string& program() const { return program_; }
  const std::vector<OptionInfo>& options() const { return infos_; }
  void set_version(std::string v) { version_ = std::move(v); }
  void add_env(std::string name, std::string help) { env_.push_back({name, help}); }
  const std::vector<EnvVar>& environment() const { return env_; }

  std::string help() const;
  // The help lines of one section's options alone, for a help text written around them.
  std::string section_help(const std::string& section) const;
  // The README's table: one row per option (option, default, reaches, meaning), then one
  // per environment variable.
  std::string markdown() const;
  [[noreturn]] void usage_error(const std::string& what) const;
  // The option an unknown `typed` name most likely meant ("--spp" for "--sammples",
  // "--quiet" for "--quite"); "" when none is near.
  std::string suggest(const std::string& typed) const;

 protected:
  // Walks argv[first, argc): "--name value", "--name=value" and switches anywhere among
  // the positional arguments. `apply` stores option i's value (nullptr for a switch).
  std::vector<std::string> walk(int argc, char** argv, int first,
                                const std::function<void(size_t, const std::string*)>& apply,
                                std::string* exit_text) const;

  std::string program_, synopsis_, description_, version_;
  std::vector<OptionInfo> infos_;
  std::vector<EnvVar> env_;
  std::string section_;
  Reach reach_ = Reach::kHost;
};

template <class T>
class OptionTable : public OptionText {
 public:
  using Apply = std::function<void(T&, const std::string*)>;
  using Show = std::function<std::string(const T&)>;

  OptionTable(std::string program, std::string synopsis, std::string description, T defaults = T())
      : OptionText(std::move(program), std::move(synopsis), std::move(description)),
        defaults_(std::move(defaults)) {}

  const T& defaults() const { return defaults_; }

  // Options declared after this belong to `title` in --help, and reach where `reach` says.
  OptionTable& section(std::string title, Reach reach = Reach::kHost) {
    section_ = std::move(title);
    reach_ = reach;
    return *this;
  }

  // A switch: sets the bool field to `value`. `names` is "--name" or "--name,-n".
  template <class Get>
  OptionTable& flag(const std::string& names, Get get, std::string help, bool value = true) {
    return add(
        names, "", std::move(help), [get, value](T& t, const std::string*) { get(t) = value; },
        nullptr);
  }

  // A whole number within `range`, into any integer field.
  template <class Get>
  OptionTable& integer(const std::string& names, std::string metavar, Range range, Get get,
                       std::string help) {
    using V = std::remove_reference_t<decltype(get(std::declval<T&>()))>;
    return add(
        names, std::move(metavar), std::move(help),
        [get, range](T& t, const std::string* v) {
          get(t) = static_cast<V>(parse_whole(*v, range));
        },
        [get](const T& t) { return std::to_string(get(const_cast<T&>(t))); });
  }

  // A number within `range`, into a float or double field.
  template <class Get>
  OptionTable& real(const std::string& names, std::string metavar, Range range, Get get,
                    std::string help) {
    using V = std::remove_reference_t<decltype(get(std::declval<T&>()))>;
    return add(
        names, std::move(metavar), std::move(help),
        [get, range](T& t, const std::string* v) {
          get(t) = static_cast<V>(parse_number(*v, range));
        },
        [get](const T& t) { return format_number(get(const_cast<T&>(t))); });
  }

  // One of named values, into a field of the values' type (enum, int or bool).
  template <class Get, class V>
  OptionTable& choice(const std::string& names, std::vector<std::pair<std::string, V>> choices,
                      Get get, std::string help) {
    std::string metavar, listed;
    for (const auto& c : choices) {
      metavar += (metavar.empty() ? "" : "|") + c.first;
      listed += (listed.empty() ? "" : ", ") + c.first;
    }
    return add(
        names, metavar, std::move(help),
        [get, choices, listed](T& t, const std::string* v) {
          for (const auto& c : choices)
            if (c.first == *v) {
              get(t) = c.second;
              return;
            }
          throw UsageError("is not one of " + listed);
        },
        [get, choices](const T& t) {
          for (const auto& c : choices)
            if (c.second == get(const_cast<T&>(t))) return c.first;
          return std::string();
        });
  }

  // Any text, into a std::string field (shown as default when not empty).
  template <class Get>
  OptionTable& text(const std::string& names, std::string metavar, Get get, std::string help) {
    return add(
        names, std::move(metavar), std::move(help),
        [get](T& t, const std::string* v) { get(t) = *v; },
        [get](const T& t) { return get(const_cast<T&>(t)); });
  }

  // A comma-separated list, each item parsed by `item` (e.g. parse_number with a range);
  // replaces the default list. With `repeat`, each use appends its whole value instead.
  template <class Get, class Item>
  OptionTable& list(const std::string& names, std::string metavar, Get get, Item item,
                    std::string help, bool repeat = false) {
    return add(
        names, std::move(metavar), std::move(help),
        [get, item, repeat](T& t, const std::string* v) {
          auto& out = get(t);
          if (repeat) {
            out.push_back(item(*v));
            return;
          }
          out.clear();
          for (const std::string& s : split_commas(*v)) out.push_back(item(s));
        },
        [get](const T& t) {
          std::string s;
          for (const auto& x : get(const_cast<T&>(t))) s += (s.empty() ? "" : ",") + show_item(x);
          return s;
        });
  }

  // Replaces the last option's shown default by words, for values that mean something
  // other than themselves (a thread count 0 that means "all cores").
  OptionTable& default_is(std::string words) {
    infos_.back().default_text = std::move(words);
    infos_.back().default_in_words = true;
    return *this;
  }

  // Mounts every option of `other` (a table over U), reached through `get` (T& -> U&),
  // in their sections; used for the render options several executables share.
  template <class U, class Get>
  OptionTable& include(const OptionTable<U>& other, Get get) {
    for (size_t i = 0; i < other.options().size(); ++i) {
      auto apply = other.apply_fn(i);
      auto show = other.show_fn(i);
      infos_.push_back(other.options()[i]);
      applies_.push_back([get, apply](T& t, const std::string* v) { apply(get(t), v); });
      shows_.push_back(show ? Show([get, show](const T& t) { return show(get(const_cast<T&>(t))); })
                            : Show());
      refresh_default(infos_.size() - 1);
    }
    return *this;
  }

  // Parses argv[first, argc) into *out (which holds the defaults) and returns the positional
  // arguments. Throws UsageError; sets *exit_text to what --help or --version print.
  std::vector<std::string> parse(int argc, char** argv, T* out, std::string* exit_text,
                                 int first = 1) const {
    return walk(
        argc, argv, first, [&](size_t i, const std::string* v) { applies_[i](*out, v); },
        exit_text);
  }

  // As parse, for a main(): prints --help/--version and exits 0, or prints the one-line
  // usage error and exits 2.
  std::vector<std::string> parse_or_exit(int argc, char** argv, T* out, int first = 1) const {
    std::string exit_text;
    std::vector<std::string> positional;
    try {
      positional = parse(argc, argv, out, &exit_text, first);
    } catch (const UsageError& e) {
      usage_error(e.what());
    }
    if (!exit_text.empty()) {
      std::fputs(exit_text.c_str(), stdout);
      std::exit(0);
    }
    return positional;
  }

  const Apply& apply_fn(size_t i) const { return applies_[i]; }
  const Show& show_fn(size_t i) const { return shows_[i]; }

 private:
  static std::string format_number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
  }
  static std::string show_item(const std::string& s) { return s; }
  template <class X>
  static std::string show_item(const X& x) {
    return std::is_integral<X>::value ? std::to_string(x) : format_number(x);
  }

  OptionTable& add(const std::string& names, std::string metavar, std::string help, Apply apply,
                   Show show) {
    OptionInfo info;
    info.names = split_commas(names);
    info.metavar = std::move(metavar);
    info.help = std::move(help);
    info.section = section_;
    info.reach = reach_;
    infos_.push_back(std::move(info));
    applies_.push_back(std::move(apply));
    shows_.push_back(std::move(show));
    refresh_default(infos_.size() - 1);
    return *this;
  }
  void refresh_default(size_t i) {
    if (shows_[i] && !infos_[i].default_in_words) infos_[i].default_text = shows_[i](defaults_);
  }

  T defaults_;
  std::vector<Apply> applies_;
  std::vector<Show> shows_;
};

}  // namespace rt
