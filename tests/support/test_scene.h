// The one small scene the tests share, the text edits they make to it, the check of a
// rejected scene, and a fixture that gives each test its own temporary directory.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

#include "scene/scene.h"

namespace rt::test {

// A tiny scene (16 x 8 pixels, a two-triangle mesh, a triangle and a sphere, one point light,
// one Blinn-Phong material) that loads and renders in milliseconds; its image is simple.png.
// The near plane and the resolution share the aspect ratio 2, and the width and the height
// differ, so aspect-ratio and transposition mistakes show.
extern const char* const kTinyScene;

// kTinyScene with its mesh's faces read from the PLY file `ply` (relative to the scene).
std::string tiny_scene_with_ply_mesh(const std::string& ply);

// `s` with `from` replaced by `to`; `from` must occur exactly once (a test failure
// otherwise), so that a change of the scene cannot silently turn an edit into a no-op.
std::string replaced(std::string s, const std::string& from, const std::string& to);

// `s` with every `from` replaced by `to`.
std::string replaced_all(std::string s, const std::string& from, const std::string& to);

// Several replacements in turn, each under the rule of replaced().
using Edits = std::vector<std::pair<std::string, std::string>>;
std::string edited(std::string s, const Edits& edits);

// The bytes of a file ("" when unreadable).
std::string slurp(const std::filesystem::path& p);

// Loads the scene at `path`, expecting an rt::InputError of one line that starts with the
// file's path and contains every one of `parts`; returns the message ("" when none).
std::string expect_load_error(const std::string& path, std::initializer_list<std::string> parts);
// The same for scene text `xml` loaded under the name `name`.
std::string expect_load_text_error(const std::string& xml, const std::string& name,
                                   std::initializer_list<std::string> parts,
                                   const LoadOptions& options = {});

// A fixture with a fresh temporary directory per test, removed afterwards.
class TempDirTest : public ::testing::Test {
 protected:
  void SetUp() override;
  void TearDown() override;

  // Writes `text` to `name` (folders created as needed) in the test's directory; returns
  // its path.
  std::string write(const std::string& name, const std::string& text);

  std::filesystem::path dir_;
};

// A camera at `eye` looking down -z through a 1x1 image whose film is so narrow that
// every sample's ray passes (to within 1e-7 relative) through the same point.
CameraDesc PointCamera(Vec3d eye, int samples);

}  // namespace rt::test
