// The executable prepares each rendered camera once: the memory check before the first
// render needs no placement of its own, so the top level is built once per image
// (the --stats line's "top levels built" counts them for the scene file).
#include <gtest/gtest.h>

#include <regex>
#include <string>
#include <vector>

#include "support/cli_harness.h"

namespace {

using namespace rt::test;

std::string camera(int id, const std::string& position, const std::string& image) {
  return "<Camera id=\"" + std::to_string(id) + "\"><Position>" + position +
         "</Position><Gaze>0 0 -1</Gaze><Up>0 1 0</Up><NearPlane>-1 1 -0.5 0.5</NearPlane>"
         "<NearDistance>1</NearDistance><ImageResolution>16 8</ImageResolution><ImageName>" +
         image + "</ImageName></Camera>";
}

// The counts of every --stats line, in order.
std::vector<int> top_levels_built(const std::string& err) {
  std::vector<int> out;
  const std::regex count("top levels built ([0-9]+)");
  for (std::sregex_iterator m(err.begin(), err.end(), count), end; m != end; ++m)
    out.push_back(std::stoi((*m)[1]));
  return out;
}

class PrepareOnce : public CliFixture {};

TEST_F(PrepareOnce, TheTopLevelIsBuiltOncePerRenderedCamera) {
  const std::string scene =
      write("three.xml",
            replaced(kTinyScene, "</Cameras>",
                     camera(2, "1 0 0", "b.png") + camera(3, "0 1 0", "c.png") + "</Cameras>"));
  Outcome r = render(scene, "--stats");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(top_levels_built(r.err), (std::vector<int>{1, 2, 3})) << r.err;
  EXPECT_EQ(output_files().size(), 3u);
  // One camera of the three: one top level.
  r = render(scene, "--stats --camera 1");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(top_levels_built(r.err), (std::vector<int>{1})) << r.err;
}

}  // namespace
