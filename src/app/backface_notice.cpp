#include "backface_notice.h"

#include <cmath>
#include <cstdio>

namespace rt {

double back_face_share(const Camera& cam, const std::vector<PrimaryInfo>& primary) {
  const size_t pixels = static_cast<size_t>(cam.width) * cam.height;
  if (pixels == 0) return 0;
  return static_cast<double>(back_face_pixels(cam, primary, 0, cam.height)) /
         static_cast<double>(pixels);
}

uint64_t back_face_pixels(const Camera& cam, const std::vector<PrimaryInfo>& primary, int row_begin,
                          int row_end) {
  if (primary.size() < static_cast<size_t>(cam.width) * cam.height) return 0;
  // The pinhole ray through each pixel centre; a lens or the course's film rounding moves
  // a ray by far less than would turn a surface around.
  const float du = (cam.right - cam.left) / cam.width, dv = (cam.top - cam.bottom) / cam.height;
  uint64_t back = 0;
  for (int y = row_begin; y < row_end; ++y)
    for (int x = 0; x < cam.width; ++x) {
      const PrimaryInfo& p = primary[static_cast<size_t>(y) * cam.width + x];
      if (p.instance < 0 || !std::isfinite(p.t)) continue;  // A miss.
      const float su = cam.left + (x + 0.5f) * du, sv = cam.top - (y + 0.5f) * dv;
      const float3 d = cam.u * su + cam.v * sv - cam.w * cam.near_distance;
      if (d.x * p.normal.x + d.y * p.normal.y + d.z * p.normal.z > 0) ++back;
    }
  return back;
}

std::string back_face_notice(double share) {
  if (!(share >= kBackFaceNoticeShare)) return "";
  char buf[256];
  std::snprintf(buf, sizeof buf,
                "%.0f %% of camera rays first hit the back of a surface; the course rendered "
                "such scenes with --cull-back-faces (camera rays pass through back faces)",
                100 * share);
  return buf;
}

}  // namespace rt
