// The one hint a render gives when its scene was built for back-face culling: the course
// rendered hw1 and some hw3 scenes with camera rays that skip surfaces seen from behind
// (--cull-back-faces), and cornellbox_boxes_dynamic puts its camera outside the box's
// front wall, so without culling the image is that wall's back. A large share of camera
// rays whose first hit is the back of a surface is the sign.
#pragma once

#include <string>
#include <vector>

#include "cl/film/film_types.h"
#include "cl/scene_types.h"

namespace rt {

// The share of pixels above which the notice is given. Closed scenes seen from outside
// show back faces only where a smooth mesh's shading normal tilts away at a silhouette or
// through a thin open surface seen from behind: 0 to a few percent of the course's scenes
// (the figures are in tests/app/progress_test.sh's notes). A camera behind a wall sees the
// wall's back over most of the image (cornellbox_boxes_dynamic: well over half).
constexpr double kBackFaceNoticeShare = 0.10;

// The share (0..1) of the pixels of `primary` (the film's first-hit facts, as rendered
// by camera `cam`) whose first camera ray hit a surface from behind: the ray through the
// pixel centre points the way the recorded normal does.
double back_face_share(const Camera& cam, const std::vector<PrimaryInfo>& primary);

// The notice's text for `share`, or "" when it is below kBackFaceNoticeShare.
std::string back_face_notice(double share);

}  // namespace rt
