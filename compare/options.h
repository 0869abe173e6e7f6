// The options of `compare`, one table per subcommand (src/util/args.h): each option is
// declared once, and `compare --help` is written around the tables' generated lines.
#pragma once

#include <string>

#include "exact.h"
#include "family.h"
#include "paired.h"
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
};

// The table of one subcommand (welch, paired, exact or diff); nullptr for another name.
const rt::OptionTable<CompareOptions>* subcommand_table(const std::string& name);

// `compare --help`: what each subcommand tests, with its options.
std::string compare_help();

}  // namespace cmp
