#include "mat4.h"

namespace rt {

Mat4 operator*(const Mat4& a, const Mat4& b) {
  Mat4 r;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      double s = 0;
      for (int k = 0; k < 4; ++k) s += a(i, k) * b(k, j);
      r(i, j) = s;
    }
  return r;
}

Mat4 Mat4::translation(Vec3d t) {
  Mat4 r;
  r(0, 3) = t.x;
  r(1, 3) = t.y;
  r(2, 3) = t.z;
  return r;
}

Mat4 Mat4::scaling(Vec3d s) {
  Mat4 r;
  r(0, 0) = s.x;
  r(1, 1) = s.y;
  r(2, 2) = s.z;
  return r;
}

Mat4 Mat4::rotation(double degrees, Vec3d axis) {
  Vec3d a = normalize(axis);
  double th = degrees * M_PI / 180.0, c = std::cos(th), s = std::sin(th), t = 1 - c;
  Mat4 r;
  r(0, 0) = t * a.x * a.x + c;
  r(0, 1) = t * a.x * a.y - s * a.z;
  r(0, 2) = t * a.x * a.z + s * a.y;
  r(1, 0) = t * a.x * a.y + s * a.z;
  r(1, 1) = t * a.y * a.y + c;
  r(1, 2) = t * a.y * a.z - s * a.x;
  r(2, 0) = t * a.x * a.z - s * a.y;
  r(2, 1) = t * a.y * a.z + s * a.x;
  r(2, 2) = t * a.z * a.z + c;
  return r;
}

bool Mat4::is_identity() const { return m == Mat4().m; }

Vec3d Mat4::point(Vec3d p) const {
  const Mat4& a = *this;
  return {a(0, 0) * p.x + a(0, 1) * p.y + a(0, 2) * p.z + a(0, 3),
          a(1, 0) * p.x + a(1, 1) * p.y + a(1, 2) * p.z + a(1, 3),
          a(2, 0) * p.x + a(2, 1) * p.y + a(2, 2) * p.z + a(2, 3)};
}

Vec3d Mat4::vector(Vec3d v) const {
  const Mat4& a = *this;
  return {a(0, 0) * v.x + a(0, 1) * v.y + a(0, 2) * v.z,
          a(1, 0) * v.x + a(1, 1) * v.y + a(1, 2) * v.z,
          a(2, 0) * v.x + a(2, 1) * v.y + a(2, 2) * v.z};
}

Mat4 Mat4::affine_inverse(bool* ok) const {
  const Mat4& a = *this;
  // Inverse of the 3x3 part by cofactors, then the translation follows.
  double c00 = a(1, 1) * a(2, 2) - a(1, 2) * a(2, 1);
  double c01 = a(1, 2) * a(2, 0) - a(1, 0) * a(2, 2);
  double c02 = a(1, 0) * a(2, 1) - a(1, 1) * a(2, 0);
  double det = a(0, 0) * c00 + a(0, 1) * c01 + a(0, 2) * c02;
  Mat4 r;
  *ok = std::isfinite(det) && det != 0.0;
  if (!*ok) return r;
  double inv = 1.0 / det;
  r(0, 0) = c00 * inv;
  r(0, 1) = (a(0, 2) * a(2, 1) - a(0, 1) * a(2, 2)) * inv;
  r(0, 2) = (a(0, 1) * a(1, 2) - a(0, 2) * a(1, 1)) * inv;
  r(1, 0) = c01 * inv;
  r(1, 1) = (a(0, 0) * a(2, 2) - a(0, 2) * a(2, 0)) * inv;
  r(1, 2) = (a(0, 2) * a(1, 0) - a(0, 0) * a(1, 2)) * inv;
  r(2, 0) = c02 * inv;
  r(2, 1) = (a(0, 1) * a(2, 0) - a(0, 0) * a(2, 1)) * inv;
  r(2, 2) = (a(0, 0) * a(1, 1) - a(0, 1) * a(1, 0)) * inv;
  Vec3d t{a(0, 3), a(1, 3), a(2, 3)};
  Vec3d it = r.vector(t);
  r(0, 3) = -it.x;
  r(1, 3) = -it.y;
  r(2, 3) = -it.z;
  return r;
}

}  // namespace rt
