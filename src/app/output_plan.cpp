#include "output_plan.h"

#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>
#include <unordered_map>
#include <utility>

#include "io/file_util.h"
#include "output_check.h"
#include "render_job.h"
#include "scene/xml_text.h"
#include "util/errors.h"

namespace rt {
namespace {

namespace fs = std::filesystem;

std::string folded(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// Device and inode of an existing file: hard links, which no spelling of the path shows.
bool file_id(const std::string& path, std::pair<dev_t, ino_t>* id) {
  struct stat st;
  if (::stat(path.c_str(), &st) != 0) return false;
  *id = {st.st_dev, st.st_ino};
  return true;
}

}  // namespace

OutputPlan plan_outputs(const CliOptions& opt) {
  OutputPlan plan;
  LoadOptions outline = opt.load;
  outline.outline = true;
  for (int i = 0; i < static_cast<int>(opt.scenes.size()); ++i) {
    JobScene s;
    s.path = opt.scenes[i];
    s.desc = load_scene(s.path, outline);
    check_camera_choice(opt, s);
    for (const std::string& f : s.desc.inputs) plan.inputs.emplace_back(f, i);
    for (int c = 0; c < static_cast<int>(s.desc.cameras.size()); ++c) {
      if (opt.camera >= 0 && c != opt.camera) continue;
      const CameraDesc& cam = s.desc.cameras[c];
      for (const CameraOutput& f : camera_outputs(opt, cam, image_path(opt, s, c))) {
        PlannedOutput o{f.path,
                        fs::path(f.path).lexically_relative(opt.output_dir).string(),
                        f.what,
                        i,
                        c,
                        cam.element,
                        cam.image_name};
        // A checkpoint is written only when checkpoints are kept (image_checkpoint.h), but
        // is removed when the image is done: in the plan always, its name checked only then.
        const bool written = !f.checkpoint || opt.checkpoint_s > 0 || opt.resume;
        const std::string why = written ? output_file_problem(opt.output_dir, o.path) : "";
        if (!why.empty())
          throw input_error(s.path, cam.element,
                            "'" + shorten(cam.image_name) + "': the " + o.what + " " + why);
        plan.outputs.push_back(std::move(o));
      }
    }
  }
  return plan;
}

void check_job_outputs(const CliOptions& opt) {
  const OutputPlan plan = plan_outputs(opt);
  auto refuse = [&](const PlannedOutput& o, const std::string& why) {
    throw input_error(opt.scenes[o.scene], o.element,
                      "'" + shorten(o.image_name) + "': the " + o.what + " " + why);
  };
  // Two writers of one file: the later is named first, as the one that would replace.
  std::unordered_map<std::string, size_t> written;
  for (size_t k = 0; k < plan.outputs.size(); ++k) {
    const PlannedOutput& o = plan.outputs[k];
    const auto [it, first] = written.emplace(same_file_key(o.path), k);
    if (first) continue;
    const PlannedOutput& other = plan.outputs[it->second];
    const std::string same =
        o.name == other.name ? "two outputs share '" + shorten(o.name) + "'"
        : folded(o.name) == folded(other.name)
            ? "'" + shorten(other.name) + "' and '" + shorten(o.name) +
                  "' differ only in letter case (one file where the file system folds case)"
            : "'" + shorten(other.name) + "' and '" + shorten(o.name) + "' are one file";
    refuse(o, "would replace the " + std::string(other.what) + " of camera " +
                  std::to_string(other.camera) + " (" + other.element + ")" +
                  (other.scene != o.scene ? " of " + opt.scenes[other.scene] : "") + ": " + same);
  }
  // A writer over an input: by path, and for existing files by the file itself.
  std::unordered_map<std::string, size_t> read;
  std::map<std::pair<dev_t, ino_t>, size_t> read_ids;
  for (size_t k = 0; k < plan.inputs.size(); ++k) {
    if (!read.emplace(same_file_key(plan.inputs[k].first), k).second) continue;
    std::pair<dev_t, ino_t> id;
    if (file_id(plan.inputs[k].first, &id)) read_ids.emplace(id, k);
  }
  for (const PlannedOutput& o : plan.outputs) {
    auto it = read.find(same_file_key(o.path));
    size_t input = it == read.end() ? plan.inputs.size() : it->second;
    std::pair<dev_t, ino_t> id;
    if (input == plan.inputs.size() && file_id(o.path, &id)) {
      const auto found = read_ids.find(id);
      if (found != read_ids.end()) input = found->second;
    }
    if (input == plan.inputs.size()) continue;
    const auto& [file, scene] = plan.inputs[input];
    refuse(o, "would overwrite the input file '" + shorten(file, 200) + "'" +
                  (scene != o.scene ? " of " + opt.scenes[scene] : ""));
  }
}

}  // namespace rt
