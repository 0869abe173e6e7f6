// The options of `compare`, one table per subcommand (src/util/args.h): each option is
// declared once, and `compare --help` is written around the tables' generated lines.
#pragma once

#include <string>
#include <vector>

#include "exact.h"
#include "family.h"
#include "paired.h"
#include "reference_criterion.h"
#include "util/args.h"
#include "welch.h"

namespace cmp {

struct CompareOptions {
  FamilyOptions family;
  WelchOptions welch;  // Also diff --moments.
  PairedOptions paired;
  ExactOptions exact;
  bool allow_weighted = false;
  bool unpooled = false;  // welch: never pool, even when the sample counts differ.
  std::string out_dir;
  double gain = 4;
  int threshold = 8, downsample = 4;
  std::string out, moments;
  int report_tile = 16, worst = 6;  // report: tile edge, tiles enlarged.
  std::string criterion;            // reference: a course_scenes.txt CRITERION; empty: look up.
  std::string scenes_list;          // reference: the list to look the criterion up in.
  bool double_precision = false;    // reference: the render computed in double.
};

// The table of one subcommand (welch, paired, exact, diff, report, reference or summary);
// nullptr for another name.
const rt::OptionTable<CompareOptions>* subcommand_table(const std::string& name);

// The options and the `count` files of subcommand `sub` (argv[1]); bad usage exits with
// status 2 after one line naming the problem.
CompareOptions parse_subcommand(const char* sub, int argc, char** argv,
                                std::vector<std::string>* files, size_t count = 2);

// `compare --help`: what each subcommand tests, with its options.
std::string compare_help();

}  // namespace cmp
