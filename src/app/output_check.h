// Checks, before anything is rendered, that every image the run will write can be written
// and harms nothing: so a long render never ends in a refused or clobbering write.
#pragma once

#include <string>

#include "scene/scene.h"

namespace rt {

// Throws rt::InputError (or std::runtime_error for the folder itself), one line, when
// - the output folder is missing, not a folder, or not writable;
// - two rendered cameras (camera < 0: all of them) would write the same file;
// - an output would replace one of the scene's inputs (the scene file, a PLY), or is a folder;
// - a file name exceeds the file system's NAME_MAX or the path its PATH_MAX.
// - an image's folder (ImageName "renders/a.png") does not exist below the output folder.
// Every file a camera writes is checked: its image, the tone-mapped .png beside an .exr of
// a camera with <Tonemap>, and with `moments` each image's <name>.moments.exr.
void check_outputs(const SceneDesc& scene, int camera, const std::string& output_dir, bool moments);

}  // namespace rt
