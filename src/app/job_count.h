// The number of images a job will write, known before its scenes are loaded, for the
// progress line's "[k/n]": loading every scene file first would cost the time and memory
// of all of them before the first image starts.
#pragma once

#include <string>

namespace rt {

// The <Camera> elements of the scene file at `path`, counted by a scan of its text (XML
// comments skipped), without parsing or loading anything else; 0 when it cannot be read
// (loading it then fails with the reason). The driver corrects its total by each file's
// real count once the file is loaded.
int count_scene_cameras(const std::string& path);

}  // namespace rt
