// The subcommands for a person and for existing images: report (an HTML page), reference
// (the reference tests' criterion on a render already made) and summary (one file).
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "commands.h"
#include "inputs.h"
#include "options.h"
#include "reference_criterion.h"
#include "report_html.h"
#include "report_model.h"
#include "summary.h"

namespace cmp {

int run_report(int argc, char** argv) {
  std::vector<std::string> files;
  CompareOptions o = parse_subcommand("report", argc, argv, &files);
  if (o.out.empty())
    subcommand_table("report")->usage_error("report needs --out FILE.html or --out DIR");
  std::string note;
  Side a = load_side(files[0], true, &note), b = load_side(files[1], true, &note);
  ReportOptions ro;
  ro.tile = o.report_tile;
  ro.worst = o.worst;
  ro.family = o.family;
  ro.welch = o.welch;
  ro.paired = o.paired;
  Analysis r = analyse(a, b, ro);
  std::string path = report_path(o.out);
  write_report(path, report_html(a, b, r, ro));
  if (!note.empty()) std::printf("note: %s\n", note.c_str());
  std::printf("%s\nwrote %s\n", r.words.c_str(), path.c_str());
  return 0;
}

int run_reference(int argc, char** argv) {
  std::vector<std::string> files;
  CompareOptions o = parse_subcommand("reference", argc, argv, &files);
  std::string spec = o.criterion, source = "--criterion";
  if (spec.empty()) {
    std::string name;
    if (!find_course_criterion(o.scenes_list, files[1], &name, &spec))
      throw std::runtime_error(files[1] + " is not a reference image of " + o.scenes_list +
                               ": give its criterion with --criterion");
    source = name + " in " + o.scenes_list;
  }
  ReferenceCriterion c;
  std::string error;
  if (!parse_criterion(spec, &c, &error))
    subcommand_table("reference")->usage_error(source + ": " + error);
  rt::Image8 render = rt::read_png(files[0]), ref = rt::read_png(files[1]);
  require_same_size(files[0], render.width, render.height, files[1], ref.width, ref.height);
  std::printf("reference: criterion %s (%s)%s\n", spec.c_str(), source.c_str(),
              o.double_precision ? ", render in double" : "");
  ReferenceResult r = check_reference(render, ref, c, o.double_precision);
  std::string detail =
      files[0] + ", " + std::to_string(render.width) + "x" + std::to_string(render.height);
  print_reference_result(files[1], detail, r, c, static_cast<long>(render.width) * render.height);
  return r.pass ? 0 : 1;
}

int run_summary(int argc, char** argv) {
  std::vector<std::string> files;
  parse_subcommand("summary", argc, argv, &files, 1);
  std::fputs(summarise(files[0]).c_str(), stdout);
  return 0;
}

}  // namespace cmp
