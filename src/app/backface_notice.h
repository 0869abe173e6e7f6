// The one hint a render gives when its scene was built for back-face culling: the course
// rendered hw1 and some hw3 scenes with camera rays that skip surfaces seen from behind
// (--cull-back-faces), and cornellbox_boxes_dynamic puts its camera outside the box's
// front wall, so without culling the image is that wall's back. A large share of camera
// rays whose first hit is the back of a surface is the sign.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "cl/film/film_types.h"
#include "cl/scene_types.h"

namespace rt {

// The share of pixels from which the notice is given. Closed scenes seen from outside
// show back faces only where a smooth mesh's shading normal tilts away at a silhouette or
// through thin open surfaces seen from behind. Measured on the 74 loadable scenes of
// tests/course/course_scenes.txt without culling (quarter resolution, 1 spp): 0 % for most,
// at most 1.1 % in hw1 (windmill_smooth), 6.5 % for hw2 grass_desert (grass blades from
// behind, which the course rendered without culling); the camera behind a wall of
// cornellbox_boxes_dynamic (hw3, spring2021) sees back faces over 100 %. 20 % keeps three
// times grass_desert's share as margin, and a wall's back over a fifth of the view is
// what culling visibly changes.
constexpr double kBackFaceNoticeShare = 0.20;

// The share (0..1) of the pixels of `primary` (the film's first-hit facts, as rendered
// by camera `cam`) whose first camera ray hit a surface from behind: the ray through the
// pixel centre points the way the recorded normal does.
double back_face_share(const Camera& cam, const std::vector<PrimaryInfo>& primary);

// The count of those pixels in rows [row_begin, row_end) (a distributed rank's band; the
// film `primary` is the whole image's).
uint64_t back_face_pixels(const Camera& cam, const std::vector<PrimaryInfo>& primary, int row_begin,
                          int row_end);

// The notice's text for `share`, or "" when it is below kBackFaceNoticeShare.
std::string back_face_notice(double share);

}  // namespace rt
