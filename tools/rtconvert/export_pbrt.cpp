// pbrt-v4's text scene format. pbrt is a physically based path tracer: geometry, cameras,
// lights and the mirror/conductor/dielectric materials map; the course's Whitted-style
// extras (Blinn-Phong specular, ambient light, background seen by camera rays, epsilons)
// do not, and the file's first lines list what was left out.
#include <cmath>
#include <map>
#include <sstream>

#include "convert.h"
#include "prepare/flat_scene.h"

namespace rtconvert {
namespace {

using rt::Mat4;
using rt::Vec3d;

std::string v(Vec3d a) {
  std::ostringstream s;
  s.precision(9);
  s << a.x << " " << a.y << " " << a.z;
  return s.str();
}
std::string v(float3 a) { return v(Vec3d{a.x, a.y, a.z}); }

// pbrt's Transform takes the matrix column by column.
std::string transform(const Mat4& m) {
  std::ostringstream s;
  s.precision(17);
  s << "Transform [";
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) s << " " << m(r, c);
  s << " ]";
  return s.str();
}

std::string material(const Material& m) {
  std::ostringstream s;
  s.precision(9);
  switch (m.type) {
    case RT_MATERIAL_MIRROR:
      s << "Material \"conductor\" \"rgb reflectance\" [ " << v(m.mirror)
        << " ] \"float roughness\" " << m.roughness;
      break;
    case RT_MATERIAL_CONDUCTOR:
      s << "Material \"conductor\" \"spectrum eta\" [ 300 " << m.refraction_index << " 800 "
        << m.refraction_index << " ] \"spectrum k\" [ 300 " << m.absorption_index << " 800 "
        << m.absorption_index << " ] \"float roughness\" " << m.roughness;
      break;
    case RT_MATERIAL_DIELECTRIC:
      s << "Material \"dielectric\" \"float eta\" " << m.refraction_index << " \"float roughness\" "
        << m.roughness;
      break;
    default:
      s << "Material \"diffuse\" \"rgb reflectance\" [ " << v(m.diffuse) << " ]";
  }
  return s.str();
}

void mesh_shape(std::ostream& o, const rt::MeshDesc& mesh) {
  o << "  Shape \"trianglemesh\"\n    \"point3 P\" [";
  for (const Vec3d& p : mesh.positions) o << " " << v(p);
  o << " ]\n    \"integer indices\" [";
  for (const auto& t : mesh.triangles) o << " " << t[0] << " " << t[1] << " " << t[2];
  o << " ]\n";
  if (mesh.smooth) {
    o << "    \"normal N\" [";
    for (const Vec3d& n : rt::vertex_normals(mesh)) o << " " << v(n);
    o << " ]\n";
  }
}

bool moving(const rt::ObjectDesc& o) {
  return o.motion.x != 0 || o.motion.y != 0 || o.motion.z != 0;
}

// The object's transform, and with motion blur a second one at the shutter's close.
void place(std::ostream& o, const rt::ObjectDesc& obj) {
  if (!moving(obj)) {
    o << "  " << transform(obj.transform) << "\n";
    return;
  }
  o << "  ActiveTransform StartTime\n  " << transform(obj.transform)
    << "\n  ActiveTransform EndTime\n  " << transform(Mat4::translation(obj.motion) * obj.transform)
    << "\n  ActiveTransform All\n";
}

}  // namespace

void export_pbrt(const rt::SceneDesc& s, const std::string& path, Report& report) {
  std::ostringstream o;
  o.precision(9);
  int plain_specular = 0, absorbing = 0;
  for (const auto& m : s.materials) {
    plain_specular +=
        m.type == RT_MATERIAL_PLAIN && (m.specular.x > 0 || m.specular.y > 0 || m.specular.z > 0);
    absorbing += m.absorption.x > 0 || m.absorption.y > 0 || m.absorption.z > 0;
  }
  std::ostringstream lost;
  lost << "# Not mapped from the course's scene (pbrt-v4 is a physically based path tracer):\n"
       << "#  - Blinn-Phong SpecularReflectance/PhongExponent (" << plain_specular
       << " materials): \"diffuse\" only\n"
       << "#  - AmbientReflectance and AmbientLight " << v(s.ambient) << "\n"
       << "#  - BackgroundColor " << v(s.background) << " (black environment)\n"
       << "#  - AbsorptionCoefficient of " << absorbing << " dielectrics (needs a medium)\n"
       << "#  - ShadowRayEpsilon " << s.shadow_epsilon << ", IntersectionTestEpsilon "
       << s.intersection_epsilon << "\n"
       << "#  - MaxRecursionDepth " << s.max_depth << " becomes the path depth\n"
       << "#  - area lights are not visible in the course's images; in pbrt they are\n"
       << "#  - the square lens of ApertureSize becomes a disk of the same area\n"
       << "#  - cameras after the first (" << (s.cameras.empty() ? 0 : s.cameras.size() - 1)
       << "): pbrt renders one camera per file\n";
  o << lost.str();
  report.warn(path + ": pbrt-v4 export is approximate; the file's header lists what is lost");

  if (!s.cameras.empty()) {
    const rt::CameraDesc& c = s.cameras[0];
    Vec3d at = c.position + c.gaze;
    // pbrt's camera space is left-handed: mirror x so the image is not flipped (a camera
    // the course file already calls left-handed is pbrt's own).
    o << (c.left_handed ? "" : "Scale -1 1 1\n") << "LookAt " << v(c.position) << "  " << v(at)
      << "  " << v(c.up) << "\n";
    // With a 90 degree field of view, screen coordinates are x/z on the image plane: the
    // course's near plane divided by its distance is the screen window (x mirrored, as the
    // camera space is).
    double n = c.near_distance;
    std::string image = c.image_name.substr(0, c.image_name.find_last_of('.')) + ".exr";
    const double x0 = c.left_handed ? c.left : -c.right, x1 = c.left_handed ? c.right : -c.left;
    o << "Camera \"perspective\" \"float fov\" 90 \"float screenwindow\" [ " << x0 / n << " "
      << x1 / n << " " << c.bottom / n << " " << c.top / n << " ]";
    if (c.aperture > 0)
      o << " \"float lensradius\" " << c.aperture / std::sqrt(M_PI) << " \"float focaldistance\" "
        << c.focus_distance;
    o << "\nFilm \"rgb\" \"integer xresolution\" " << c.width << " \"integer yresolution\" "
      << c.height << " \"string filename\" \"" << image << "\"\n"
      << "Sampler \"zsobol\" \"integer pixelsamples\" " << c.samples << "\n";
  }
  o << "Integrator \"path\" \"integer maxdepth\" " << s.max_depth << "\n\nWorldBegin\n\n";
  for (const PointLight& l : s.point_lights)
    o << "AttributeBegin\n  LightSource \"point\" \"point3 from\" [ " << v(l.position)
      << " ] \"rgb I\" [ " << v(l.intensity) << " ]\nAttributeEnd\n";
  for (const Light& l : s.lights) {
    const Vec3d d{l.normal.x, l.normal.y, l.normal.z}, p{l.position.x, l.position.y, l.position.z};
    if (l.type == RT_LIGHT_DIRECTIONAL)
      o << "AttributeBegin\n  LightSource \"distant\" \"point3 from\" [ 0 0 0 ] \"point3 to\" [ "
        << v(d) << " ] \"rgb L\" [ " << v(l.emission) << " ]\nAttributeEnd\n";
    if (l.type == RT_LIGHT_SPOT) {
      const double cover = std::acos(RT_SPOT_COS_COVERAGE(&l)) * 180 / M_PI,
                   fall = std::acos(RT_SPOT_COS_FALLOFF(&l)) * 180 / M_PI;
      o << "AttributeBegin\n  LightSource \"spot\" \"point3 from\" [ " << v(p)
        << " ] \"point3 to\" [ " << v(p + d) << " ] \"rgb I\" [ " << v(l.emission)
        << " ] \"float coneangle\" " << cover << " \"float conedeltaangle\" " << cover - fall
        << "\nAttributeEnd\n";
    }
  }
  for (const AreaLight& a : s.area_lights) {
    Vec3d c{a.corner.x, a.corner.y, a.corner.z}, e1{a.edge1.x, a.edge1.y, a.edge1.z},
        e2{a.edge2.x, a.edge2.y, a.edge2.z};
    // The course's area lights emit from both faces (pbrt also shows them to the camera).
    o << "AttributeBegin\n  AreaLightSource \"diffuse\" \"rgb L\" [ " << v(a.radiance)
      << " ] \"bool twosided\" true\n"
      << "  Shape \"bilinearmesh\" \"point3 P\" [ " << v(c) << " " << v(c + e1) << " " << v(c + e2)
      << " " << v(c + e1 + e2) << " ]\nAttributeEnd\n";
  }
  // A mesh used by several objects becomes one pbrt object per material it wears.
  std::map<std::pair<int, int>, int> users;
  // Object lights are written one by one: pbrt's object instances cannot emit.
  for (const auto& obj : s.objects)
    if (obj.kind == rt::ObjectDesc::kMesh && !obj.emits) ++users[{obj.mesh, obj.material}];
  for (const auto& [key, count] : users) {
    if (count < 2) continue;
    o << "\nObjectBegin \"mesh" << key.first << "_material" << key.second << "\"\n  "
      << material(s.materials[key.second]) << "\n";
    mesh_shape(o, s.meshes[key.first]);
    o << "ObjectEnd\n";
  }
  for (const auto& obj : s.objects) {
    o << "\nAttributeBegin\n";
    place(o, obj);
    // LightMesh and LightSphere: a diffuse area light on the shape, emitting from the front
    // faces as the course's (pbrt's default is one-sided, on the side of the normal).
    if (obj.emits) o << "  AreaLightSource \"diffuse\" \"rgb L\" [ " << v(obj.radiance) << " ]\n";
    if (obj.kind == rt::ObjectDesc::kSphere) {
      o << "  " << material(s.materials[obj.material])
        << "\n  Shape \"sphere\" \"float radius\" 1\n";
    } else if (!obj.emits && users[{obj.mesh, obj.material}] > 1) {
      o << "  ObjectInstance \"mesh" << obj.mesh << "_material" << obj.material << "\"\n";
    } else {
      o << "  " << material(s.materials[obj.material]) << "\n";
      mesh_shape(o, s.meshes[obj.mesh]);
    }
    o << "AttributeEnd\n";
  }
  write_file_atomically(path, o.str());
}

}  // namespace rtconvert
