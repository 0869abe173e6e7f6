// The course renderer's camera rays in world space and float (RT_FLAG_COURSE_CAMERA).
#pragma once

#include "cl/scene_types.h"
#include "scene/scene.h"

namespace rt {

// Fills cam's course_eye, course_q, course_u and course_v from the file's camera, each
// rounded as the course's float arithmetic rounds it (cl/camera/camera.h, CourseCameraDirection).
void set_course_camera(Camera& cam, const CameraDesc& c);

// Whether the course's float camera rays are faithful for camera c, whose course fields
// set_course_camera has filled in cam: float's spacing at the film point's coordinates stays
// under a twentieth of a pixel on the film, as it does for the course's cameras, a few
// hundred units from the origin at most. Far from the origin the rounding would displace
// whole pixels, so such a camera keeps the camera-relative rays whatever --camera-rays says.
bool course_camera_is_faithful(const Camera& cam, const CameraDesc& c);

}  // namespace rt
