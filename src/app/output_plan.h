// The job's output plan: every file every camera of every scene file on the command line
// will write, listed before the first sample from a light first pass over the files (their
// XML and cameras; no mesh or image is read), and checked against each other and against
// every input the scene files name. Both drivers check it before anything renders: the
// single-process one (main.cpp) and rank 0 of the distributed one (distributed/job_plan.cpp).
#pragma once

#include <string>
#include <vector>

#include "cli.h"

namespace rt {

// One file the job writes.
struct PlannedOutput {
  std::string path;     // Below --output-dir, as it is written.
  std::string name;     // Relative to --output-dir, for messages.
  const char* what;     // CameraOutput::what
  int scene, camera;    // Index in CliOptions::scenes; camera in the file.
  std::string element;  // The camera's ImageName element ("Cameras > Camera id=2 > ImageName").
  std::string image_name;
};

struct OutputPlan {
  std::vector<PlannedOutput> outputs;               // In the order they are rendered.
  std::vector<std::pair<std::string, int>> inputs;  // Every file a scene names, and its scene.
};

// Lists the job's outputs and inputs (--camera's camera or every camera of each file, with
// --skip-existing and --resume too: whether a camera is rendered depends on files the plan
// is not about). Throws one line (input_error / runtime_error) when a scene file is missing
// or does not parse, when --camera names a camera a file lacks, or when an output cannot be
// written (output_check.h).
OutputPlan plan_outputs(const CliOptions& opt);

// plan_outputs, then refuses, in one line naming both cameras (scene file and the camera's
// element) and the file, two outputs that are one file (same_file_key, io/file_util.h: after
// "a/./b", --output-dir's spelling, links and letter case) and an output that would replace
// an input (also through a hard link).
void check_job_outputs(const CliOptions& opt);

}  // namespace rt
