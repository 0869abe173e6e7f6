// The checks of one output file, made for every file of the job's output plan
// (output_plan.h) before anything is rendered: so a long render never ends in a refused
// write.
#pragma once

#include <string>

namespace rt {

// Why `path`, a file written below the output folder `output_dir`, cannot be written; ""
// when it can. Refused: a file name over the file system's NAME_MAX or a path over its
// PATH_MAX; a folder (ImageName "renders/a.png") that does not exist below the output folder
// or is not a folder; a path that is a directory. Existing files are not refused:
// --skip-existing and --resume meet them, and a new render replaces them.
std::string output_file_problem(const std::string& output_dir, const std::string& path);

}  // namespace rt
