#include "course_camera.h"

#include <algorithm>
#include <cmath>

namespace rt {
namespace {

// Float arithmetic written out: each operation below is one of the course renderer's float
// roundings (-ffp-contract=off keeps them separate).
struct F3 {
  float x, y, z;
};
F3 operator+(F3 a, F3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
F3 operator-(F3 a, F3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
F3 operator*(F3 a, float s) { return {a.x * s, a.y * s, a.z * s}; }
F3 to_f3(Vec3d v) {
  return {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z)};
}
Vec3d to_d3(F3 a) { return {a.x, a.y, a.z}; }

}  // namespace

// Matched against hw1 windmill_smooth (camera 45 units from the origin), where each choice
// below changes tens to hundreds of pixels: the file's numbers are read as float; the gaze
// is normalized in float, dividing by its length (hw1 scienceTree, whose gaze is not unit
// length, has 14 pixels more off with it normalized in double, windmill 26 fewer); u and v
// follow in double and are rounded (in float: 13 more off on windmill); the film corner
// q = (e - w near + u left) + v top is summed in float (in double: 800 more).
// cl/camera/camera.h forms s and d = s - e from these in float.
void set_course_camera(Camera& cam, const CameraDesc& c) {
  const Vec3d e = to_d3(to_f3(c.position)), gaze = to_d3(to_f3(c.gaze)), up = to_d3(to_f3(c.up));
  const F3 g = to_f3(gaze);
  const float glen = std::sqrt(g.x * g.x + g.y * g.y + g.z * g.z);
  const Vec3d w = to_d3(F3{g.x / glen, g.y / glen, g.z / glen}) * -1.0;
  Vec3d u = normalize(cross(up, w));
  const Vec3d v = cross(w, u);
  if (c.left_handed) u = u * -1.0;
  const F3 ef = to_f3(e), uf = to_f3(u), vf = to_f3(v), wf = to_f3(w);
  const float near = static_cast<float>(c.near_distance);
  const F3 q = ef - wf * near + uf * static_cast<float>(c.left) + vf * static_cast<float>(c.top);
  cam.course_eye = make_float3(ef.x, ef.y, ef.z);
  cam.course_q = make_float3(q.x, q.y, q.z);
  cam.course_u = make_float3(uf.x, uf.y, uf.z);
  cam.course_v = make_float3(vf.x, vf.y, vf.z);
}

bool course_camera_is_faithful(const Camera& cam, const CameraDesc& c) {
  double magnitude = 0.0;
  for (float x : {cam.course_eye.x, cam.course_eye.y, cam.course_eye.z, cam.course_q.x,
                  cam.course_q.y, cam.course_q.z})
    magnitude = std::max(magnitude, std::fabs(static_cast<double>(x)));
  const double spacing = magnitude * std::ldexp(1.0, -23);  // At most one float ulp there.
  const double pixel =
      std::min(std::fabs(c.right - c.left) / c.width, std::fabs(c.top - c.bottom) / c.height);
  return spacing < pixel / 20.0;
}

}  // namespace rt
