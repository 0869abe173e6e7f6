// A 4x4 affine matrix in double precision for composing the scene's transformation
// chains on the host; the kernel receives float 3x4 rows.
#pragma once

#include <array>
#include <cmath>

namespace rt {

struct Vec3d {
  double x = 0, y = 0, z = 0;
};

inline Vec3d operator+(Vec3d a, Vec3d b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3d operator-(Vec3d a, Vec3d b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3d operator*(Vec3d a, double s) { return {a.x * s, a.y * s, a.z * s}; }
inline double dot(Vec3d a, Vec3d b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3d cross(Vec3d a, Vec3d b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double length(Vec3d a) { return std::sqrt(dot(a, a)); }
inline Vec3d normalize(Vec3d a) { return a * (1.0 / length(a)); }

struct Mat4 {
  std::array<double, 16> m{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

  double& operator()(int r, int c) { return m[r * 4 + c]; }
  double operator()(int r, int c) const { return m[r * 4 + c]; }

  static Mat4 translation(Vec3d t);
  static Mat4 scaling(Vec3d s);
  // Rotation by `degrees` about `axis` (any length > 0), right-handed.
  static Mat4 rotation(double degrees, Vec3d axis);

  bool is_identity() const;
  Vec3d point(Vec3d p) const;
  Vec3d vector(Vec3d v) const;
  // Inverse of an affine matrix; `ok` is false when it is singular.
  Mat4 affine_inverse(bool* ok) const;
};

Mat4 operator*(const Mat4& a, const Mat4& b);

}  // namespace rt
