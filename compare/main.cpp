// compare: checks two renders against each other, statistically (welch, paired), exactly
// (exact) or by image metrics (diff); writes a page for a person (report), checks a render
// against the course's reference (reference) and describes one file (summary). See
// compare/README.md for the method and its calibration, and compare/options.cpp for the
// options of each subcommand.
#include <cstdio>
#include <string>

#include "commands.h"
#include "options.h"

int main(int argc, char** argv) {
  std::string cmd = argc > 1 ? argv[1] : "";
  if (cmd == "--help" || cmd == "-h" || cmd == "help") {
    std::fputs(cmp::compare_help().c_str(), stdout);
    return 0;
  }
  try {
    if (cmd == "welch") return cmp::run_welch(argc, argv);
    if (cmd == "paired") return cmp::run_paired(argc, argv);
    if (cmd == "exact") return cmp::run_exact(argc, argv);
    if (cmd == "diff") return cmp::run_diff(argc, argv);
    if (cmd == "report") return cmp::run_report(argc, argv);
    if (cmd == "reference") return cmp::run_reference(argc, argv);
    if (cmd == "summary") return cmp::run_summary(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "compare: error: %s\n", e.what());
    return 2;
  }
  std::fprintf(stderr, "compare: %s (see compare --help)\n",
               cmd.empty() ? "no subcommand given" : ("unknown subcommand '" + cmd + "'").c_str());
  return 2;
}
