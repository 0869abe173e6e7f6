#include "import_lights.h"

#include <algorithm>
#include <cmath>

namespace rtconvert {
namespace {

using rt::Mat4;
using rt::Vec3d;

constexpr double kScale = kRadianceScale;

Vec3d v3(const aiVector3D& v) { return {v.x, v.y, v.z}; }

Mat4 global_transform(const aiScene& ai, const aiString& name) {
  const aiNode* n = ai.mRootNode->FindNode(name);
  Mat4 m;
  for (; n; n = n->mParent) {
    Mat4 local;
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) local(r, c) = n->mTransformation[r][c];
    m = local * m;
  }
  return m;
}

struct Bounds {
  Vec3d lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  void grow(Vec3d p) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  Vec3d centre() const { return (lo + hi) * 0.5; }
  double diagonal() const { return std::max(length(hi - lo), 1e-6); }
};

Bounds scene_bounds(const rt::SceneDesc& s) {
  Bounds b;
  for (const auto& o : s.objects) {
    if (o.kind == rt::ObjectDesc::kSphere) {
      for (int c = 0; c < 8; ++c)
        b.grow(o.transform.point({c & 1 ? 1.0 : -1.0, c & 2 ? 1.0 : -1.0, c & 4 ? 1.0 : -1.0}));
      continue;
    }
    for (const Vec3d& p : s.meshes[o.mesh].positions) b.grow(o.transform.point(p));
  }
  for (const auto& a : s.area_lights) b.grow(a.corner);
  if (b.lo.x > b.hi.x) b.grow({0, 0, 0});
  return b;
}

float3 f3(Vec3d v) { return rt::to_float3(v); }
Vec3d colour(const aiColor3D& c) { return {c.r, c.g, c.b}; }

}  // namespace

bool parallelogram_light(const aiMesh& m, const Mat4& world, float3 radiance, AreaLight& out) {
  if (m.mNumFaces != 2) return false;
  std::vector<Vec3d> corners;
  for (unsigned f = 0; f < 2; ++f)
    for (unsigned k = 0; k < m.mFaces[f].mNumIndices; ++k) {
      Vec3d p = world.point(v3(m.mVertices[m.mFaces[f].mIndices[k]]));
      bool seen = false;
      for (const Vec3d& q : corners) seen = seen || length(p - q) == 0;
      if (!seen) corners.push_back(p);
    }
  if (corners.size() != 4) return false;
  // Some corner's two neighbours span the parallelogram: p0 + e1 + e2 is the fourth.
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int k = j + 1; k < 4; ++k) {
        if (i == j || i == k) continue;
        int l = 6 - i - j - k;
        Vec3d e1 = corners[j] - corners[i], e2 = corners[k] - corners[i];
        Vec3d n = cross(e1, e2);
        double size = std::max(length(e1), length(e2));
        if (length(n) == 0 || length(corners[i] + e1 + e2 - corners[l]) > 1e-5 * size) continue;
        out = AreaLight{};
        out.corner = corners[i];
        out.edge1 = f3(e1);
        out.edge2 = f3(e2);
        out.normal = f3(normalize(n));
        out.radiance = radiance;
        out.area = static_cast<float>(length(n));
        return true;
      }
  return false;
}

void import_cameras(const aiScene& ai, const std::string& file, bool gltf, int width,
                    rt::SceneDesc& s, Report& report) {
  for (unsigned i = 0; i < ai.mNumCameras; ++i) {
    const aiCamera& c = *ai.mCameras[i];
    const std::string where = file + ": camera '" + c.mName.C_Str() + "': ";
    if (c.mOrthographicWidth > 0 || c.mHorizontalFOV <= 0)
      throw ConvertError(where + "orthographic projection (the course's cameras are perspective)");
    Mat4 t = global_transform(ai, c.mName);
    rt::CameraDesc d;
    // A glTF camera sits at its node's origin; Assimp 5.2 also copies the node's
    // translation into mPosition, which the node's transform would then apply twice.
    d.position = t.point(gltf ? Vec3d{0, 0, 0} : v3(c.mPosition));
    d.gaze = t.vector(v3(c.mLookAt));
    d.up = t.vector(v3(c.mUp));
    if (length(cross(d.gaze, d.up)) == 0)
      d.up = std::fabs(d.gaze.y) < 0.9 ? Vec3d{0, 1, 0} : Vec3d{1, 0, 0};
    double aspect = c.mAspect > 0 ? c.mAspect : 4.0 / 3.0;
    if (!(c.mAspect > 0)) report.warn(where + "no aspect ratio: 4:3 assumed");
    // Assimp's header calls mHorizontalFOV half the angle, but its FBX and Collada readers
    // store the whole angle, and its glTF 2.0 reader (5.2) stores yfov * aspectRatio, from
    // which glTF's own yfov comes back exactly.
    if (gltf) {
      d.top = std::tan(c.mHorizontalFOV / aspect / 2);
      d.right = d.top * aspect;
    } else {
      d.right = std::tan(c.mHorizontalFOV / 2);
      d.top = d.right / aspect;
    }
    d.left = -d.right;
    d.bottom = -d.top;
    d.width = width;
    d.height = std::max(1, static_cast<int>(std::lround(width / aspect)));
    d.image_name = "camera" + std::to_string(i) + ".png";
    s.cameras.push_back(d);
  }
}

void import_lights(const aiScene& ai, const std::string& file, bool photometric, rt::SceneDesc& s,
                   Report& report) {
  Bounds b = scene_bounds(s);
  for (unsigned i = 0; i < ai.mNumLights; ++i) {
    const aiLight& l = *ai.mLights[i];
    const std::string where = file + ": light '" + l.mName.C_Str() + "': ";
    Mat4 t = global_transform(ai, l.mName);
    Vec3d pos = t.point(v3(l.mPosition)), c = colour(l.mColorDiffuse);
    double d2 = std::max(dot(pos - b.centre(), pos - b.centre()), 1e-12);
    // Candela to the course's intensity: a Lambertian surface shows albedo * E / pi.
    double to_course = photometric ? kScale / M_PI : kScale * d2;
    if (!photometric)
      report.warn(where +
                  "intensity units unknown: scaled to give its colour at the scene's centre");
    switch (l.mType) {
      case aiLightSource_SPOT:
        report.warn(where + "spot light mapped to a point light (the cone is lost)");
        [[fallthrough]];
      case aiLightSource_POINT:
        s.point_lights.push_back({pos, f3(c * to_course)});
        break;
      case aiLightSource_DIRECTIONAL: {
        // A distant point light giving the same irradiance at the scene's centre.
        Vec3d dir = normalize(t.vector(v3(l.mDirection)));
        double far = 100 * b.diagonal();
        Vec3d p = b.centre() - dir * far;
        double scale = (photometric ? kScale / M_PI : kScale) * far * far;
        s.point_lights.push_back({p, f3(c * scale)});
        report.warn(where + "directional light mapped to a point light 100 scene sizes away");
        break;
      }
      case aiLightSource_AMBIENT:
        s.ambient = s.ambient + c * kScale;
        report.warn(where + "ambient light added to AmbientLight (its colour x 255)");
        break;
      case aiLightSource_AREA: {
        Vec3d dir = normalize(t.vector(v3(l.mDirection))), up = normalize(t.vector(v3(l.mUp)));
        Vec3d right = normalize(cross(up, dir));
        Vec3d e1 = right * l.mSize.x, e2 = cross(dir, right) * l.mSize.y;
        if (length(cross(e1, e2)) == 0) {
          report.warn(where + "area light without a size: dropped");
          break;
        }
        AreaLight a{};
        a.corner = pos - e1 * 0.5 - e2 * 0.5;
        a.edge1 = f3(e1);
        a.edge2 = f3(e2);
        a.normal = f3(normalize(cross(e1, e2)));
        a.radiance = f3(c * kScale);
        a.area = static_cast<float>(length(cross(e1, e2)));
        s.area_lights.push_back(a);
        break;
      }
      default:
        report.warn(where + "unknown light type, dropped");
    }
  }
}

void add_defaults(const std::string& file, int width, rt::SceneDesc& s, Report& report) {
  Bounds b = scene_bounds(s);
  if (s.cameras.empty()) {
    // Seen from the front (+z, glTF's convention), a little from the right and above.
    Vec3d dir = rt::normalize({0.4, 0.3, 1.0});
    rt::CameraDesc c;
    c.position = b.centre() + dir * (1.3 * b.diagonal());
    c.gaze = dir * -1.0;
    c.up = {0, 1, 0};
    c.top = std::tan(20 * M_PI / 180);
    c.bottom = -c.top;
    c.right = c.top * 4 / 3;
    c.left = -c.right;
    c.width = width;
    c.height = width * 3 / 4;
    c.image_name = "camera0.png";
    s.cameras.push_back(c);
    report.warn(file + ": no camera: a default one frames the scene (40 degrees vertical)");
  }
  bool object_lights = false;
  for (const auto& o : s.objects) object_lights = object_lights || o.emits;
  if (s.point_lights.empty() && s.area_lights.empty() && s.lights.empty() && !object_lights) {
    const rt::CameraDesc& c = s.cameras[0];
    Vec3d p = c.position + Vec3d{0, 0.5 * b.diagonal(), 0};
    double d2 = dot(p - b.centre(), p - b.centre());
    s.point_lights.push_back({p, f3(Vec3d{0.9, 0.9, 0.9} * (kScale * d2))});
    s.ambient = {20, 20, 20};
    for (auto& m : s.materials)
      if (m.ambient.x == 0 && m.ambient.y == 0 && m.ambient.z == 0) m.ambient = m.diffuse;
    report.warn(file + ": no light: a default point light above the camera and ambient 20");
  }
}

}  // namespace rtconvert
