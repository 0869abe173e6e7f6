// The fixture of the scene loader's tests (tests/scene/loader/): each test edits the shared tiny
// scene, writes it to its own directory and loads it, or expects the one-line error.
#pragma once

#include <initializer_list>
#include <string>

#include "support/test_scene.h"

namespace rt::test {

class LoaderTest : public TempDirTest {
 protected:
  // kTinyScene with `edits` applied, written as scene.xml; returns its path.
  std::string scene(const Edits& edits) { return write("scene.xml", edited(kTinyScene, edits)); }

  // Loads `path`, expecting an InputError whose one-line message contains every `part`.
  std::string expect_error(const std::string& path, std::initializer_list<std::string> parts) {
    return expect_load_error(path, parts);
  }
  // The same for the tiny scene with `edits` applied.
  std::string expect_error(const Edits& edits, std::initializer_list<std::string> parts) {
    return expect_load_error(scene(edits), parts);
  }
};

using LoaderErrors = LoaderTest;
using LoaderAccepts = LoaderTest;
using LoaderTransforms = LoaderTest;

}  // namespace rt::test
