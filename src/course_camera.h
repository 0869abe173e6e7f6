// The course renderer's camera rays in world space and float (RT_FLAG_COURSE_CAMERA).
#pragma once

#include "cl/scene_types.h"
#include "scene.h"

namespace rt {

// Fills cam's course_eye, course_q, course_u and course_v from the file's camera, each
// rounded as the course's float arithmetic rounds it (cl/camera.h, CourseCameraDirection).
void set_course_camera(Camera& cam, const CameraDesc& c);

}  // namespace rt
