// rtconvert as a user runs it (the built executables): textured OBJ and glTF models made
// here (a quad with a 4x4 PNG of four colours) import, render with the texture's colours
// in the right places and export back with their textures; an output that is the input is
// refused; every feature a format cannot carry gets a warning naming it; the glTF round
// trip of an hw6 scene keeps its object lights, renderer settings and tone map; and a
// conversion writes nothing into the current folder.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "course_extras.h"
#include "io/png_io.h"
#include "scene/scene.h"

namespace {

namespace fs = std::filesystem;

struct Outcome {
  int code = -1;
  std::string err;
};

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

int lines(const std::string& s) {
  int n = 0;
  for (char c : s) n += c == '\n';
  return n;
}

// The texture: red top left, green top right, blue bottom left, white bottom right.
const unsigned char kQuadrant[4][3] = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {255, 255, 255}};

class ConvertFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    char tmpl[] = "/tmp/rtconvert_files_XXXXXX";
    ASSERT_NE(mkdtemp(tmpl), nullptr);
    dir_ = tmpl;
    rt::Image8 png;
    png.width = png.height = 4;
    for (int y = 0; y < 4; ++y)
      for (int x = 0; x < 4; ++x)
        for (int c = 0; c < 3; ++c) png.rgb.push_back(kQuadrant[(y / 2) * 2 + x / 2][c]);
    rt::write_png((dir_ / "tex.png").string(), png);
    for (const char* d : {"out", "again", "back"}) fs::create_directory(dir_ / d);
  }
  // RTCONVERT_TEST_KEEP=1 keeps the folder, to look at what a failing test wrote.
  void TearDown() override {
    if (!std::getenv("RTCONVERT_TEST_KEEP")) fs::remove_all(dir_);
  }

  fs::path write(const std::string& name, const std::string& text) {
    fs::path p = dir_ / name;
    fs::create_directories(p.parent_path());
    std::ofstream(p, std::ios::binary) << text;
    return p;
  }
  // Runs `command` in folder `cwd` (the test folder by default), stderr captured.
  Outcome run(const std::string& command, const fs::path& cwd = {}) {
    const fs::path err = dir_ / "stderr.txt";
    std::string line = "cd '" + (cwd.empty() ? dir_ : cwd).string() + "' && " + command + " 2> '" +
                       err.string() + "' > /dev/null";
    Outcome r;
    int status = std::system(line.c_str());
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.err = read(err);
    fs::remove(err);
    return r;
  }
  Outcome convert(const std::string& args, const fs::path& cwd = {}) {
    return run(std::string(RTCONVERT_EXE) + " " + args, cwd);
  }
  // Renders camera 0 of `scene` with the CPU reference and returns the image.
  rt::Image8 render(const std::string& scene, const std::string& image) {
    fs::create_directories(dir_ / "renders");
    Outcome r = run(std::string(RAYTRACER_EXE) + " " + scene +
                    " --device cpu --threads 1 --spp 1 --camera 0 --quiet --output-dir renders");
    EXPECT_EQ(r.code, 0) << r.err;
    return rt::read_png((dir_ / "renders" / image).string());
  }
  // The texture's quadrant colours inside the quad, which spans the central `span` of the
  // image. The course's bilinear lookup weighs texel (i, j) with its right and lower
  // neighbours, so a 4x4 image of 2x2 quadrants is pure for u, v in [0, 1/4] and [1/2, 1]:
  // the points looked at are u, v = 1/8 and 3/4.
  void expect_quadrants(const rt::Image8& im, double span) {
    ASSERT_GT(im.width, 0);
    for (int q = 0; q < 4; ++q) {
      const double u = q % 2 ? 0.75 : 0.125, v = q / 2 ? 0.75 : 0.125;
      int x = static_cast<int>(im.width * (0.5 + (u - 0.5) * span));
      int y = static_cast<int>(im.height * (0.5 + (v - 0.5) * span));
      const uint8_t* p = &im.rgb[3 * (static_cast<size_t>(y) * im.width + x)];
      for (int c = 0; c < 3; ++c) {
        if (kQuadrant[q][c])
          EXPECT_GT(p[c], 100) << "quadrant " << q << " channel " << c << " at " << x << "," << y;
        else
          EXPECT_LT(p[c], 60) << "quadrant " << q << " channel " << c << " at " << x << "," << y;
      }
    }
  }

  fs::path dir_;
};

// A unit quad in the z = 0 plane, facing +z; OBJ's texture origin is the bottom left.
const char* kQuadObj =
    "mtllib quad.mtl\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\n"
    "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nusemtl tex\nf 1/1 2/2 3/3\nf 1/1 3/3 4/4\n";

TEST_F(ConvertFiles, ObjTexturedQuadRendersItsTextureAndExportsIt) {
  write("model/quad.obj", kQuadObj);
  write("model/quad.mtl", "newmtl tex\nKd 1 1 1\nmap_Kd ../tex.png\n");
  Outcome r = convert("model/quad.obj out/quad.xml --width 64");
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string xml = read(dir_ / "out/quad.xml");
  EXPECT_NE(xml.find("<Image id=\"1\">../tex.png</Image>"), std::string::npos) << xml;
  EXPECT_NE(xml.find("<DecalMode>replace_kd</DecalMode>"), std::string::npos);
  EXPECT_NE(xml.find("<TexCoordData>"), std::string::npos);
  EXPECT_NE(xml.find("<ImageName>quad.png</ImageName>"), std::string::npos);
  // The default camera looks at the quad from the front, a little right and above: the
  // quad fills about the middle half of the image.
  expect_quadrants(render("out/quad.xml", "quad.png"), 0.5);

  // Back to OBJ: map_Kd names the same image relative to the new MTL, and vt is written.
  r = convert("out/quad.xml again/quad2.obj");
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string mtl = read(dir_ / "again/quad2.mtl");
  ASSERT_NE(mtl.find("map_Kd ../tex.png"), std::string::npos) << mtl;
  EXPECT_NE(read(dir_ / "again/quad2.obj").find("\nvt "), std::string::npos);
  // And the OBJ written comes back textured, as another tool's file.
  r = convert("again/quad2.obj again/quad2.xml --width 64");
  ASSERT_EQ(r.code, 0) << r.err;
  expect_quadrants(render("again/quad2.xml", "quad2.png"), 0.5);
}

// A .gltf with an external buffer and image: the quad, texture coordinates (glTF's origin
// is the top left) and two cameras looking at it head on (glTF cameras look down -z).
void write_gltf(const fs::path& dir) {
  const float pos[] = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0};
  const float uv[] = {0, 1, 1, 1, 1, 0, 0, 0};
  const unsigned short idx[] = {0, 1, 2, 0, 2, 3};
  std::ofstream bin(dir / "quad.bin", std::ios::binary);
  bin.write(reinterpret_cast<const char*>(pos), sizeof pos);
  bin.write(reinterpret_cast<const char*>(uv), sizeof uv);
  bin.write(reinterpret_cast<const char*>(idx), sizeof idx);
  bin.close();
  rtconvert::json g = rtconvert::json::parse(R"({
    "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0, 1, 2]}],
    "nodes": [{"mesh": 0, "name": "quad"},
              {"camera": 0, "name": "front", "translation": [0, 0, 3]},
              {"camera": 1, "name": "far", "translation": [0, 0, 6]}],
    "cameras": [{"type": "perspective",
                 "perspective": {"yfov": 0.8, "aspectRatio": 1, "znear": 0.01}},
                {"type": "perspective",
                 "perspective": {"yfov": 0.8, "aspectRatio": 1, "znear": 0.01}}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1},
                                "indices": 2, "material": 0}]}],
    "materials": [{"name": "tex", "pbrMetallicRoughness": {"baseColorTexture": {"index": 0},
                   "metallicFactor": 0, "roughnessFactor": 1}}],
    "textures": [{"source": 0}], "images": [{"uri": "../tex.png"}],
    "buffers": [{"uri": "quad.bin", "byteLength": 92}],
    "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48},
                    {"buffer": 0, "byteOffset": 48, "byteLength": 32},
                    {"buffer": 0, "byteOffset": 80, "byteLength": 12}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
                   "min": [-1, -1, 0], "max": [1, 1, 0]},
                  {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC2"},
                  {"bufferView": 2, "componentType": 5123, "count": 6, "type": "SCALAR"}]})");
  std::ofstream(dir / "quad.gltf") << g.dump();
}

TEST_F(ConvertFiles, GltfTexturedQuadRendersItsTextureAndExportsIt) {
  fs::create_directories(dir_ / "model");
  write_gltf(dir_ / "model");
  Outcome r = convert("model/quad.gltf out/quad.xml --width 40");
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string xml = read(dir_ / "out/quad.xml");
  // Renders named after the input and its cameras; glTF's sRGB colour map degammaed.
  EXPECT_NE(xml.find("<ImageName>quad_front.png</ImageName>"), std::string::npos) << xml;
  EXPECT_NE(xml.find("<ImageName>quad_far.png</ImageName>"), std::string::npos);
  EXPECT_NE(xml.find("degamma=\"true\""), std::string::npos);
  // yfov 0.8 at distance 3: the quad spans 2 / (2 * 3 * tan 0.4) = 79% of the image.
  expect_quadrants(render("out/quad.xml", "quad_front.png"), 0.79);

  // To .glb: the image embedded, shown as baseColorTexture; read back as another tool's
  // file (--no-extras, Assimp's embedded texture) and as rtconvert's own.
  r = convert("out/quad.xml out/quad.glb");
  ASSERT_EQ(r.code, 0) << r.err;
  rtconvert::json g = rtconvert::read_gltf_json((dir_ / "out/quad.glb").string());
  ASSERT_EQ(g["images"].size(), 1u) << g.dump();
  EXPECT_TRUE(g["images"][0].contains("bufferView"));
  bool shown = false;
  for (const auto& m : g["materials"])
    shown = shown || m["pbrMetallicRoughness"].contains("baseColorTexture");
  EXPECT_TRUE(shown) << g["materials"].dump();
  for (const char* flags : {"--no-extras", ""}) {
    r = convert(std::string("out/quad.glb back/quad.xml --width 40 ") + flags);
    ASSERT_EQ(r.code, 0) << flags << r.err;
    EXPECT_TRUE(fs::exists(dir_ / "back/quad_files/tex.png")) << flags;
    expect_quadrants(render("back/quad.xml", *flags ? "quad_camera0.png" : "quad_front.png"), 0.79);
    fs::remove_all(dir_ / "back");
    fs::create_directory(dir_ / "back");
  }
}

TEST_F(ConvertFiles, OutputThatIsTheInputIsRefused) {
  write("model/quad.obj", kQuadObj);
  write("model/quad.mtl", "newmtl tex\nKd 1 1 1\nmap_Kd ../tex.png\n");
  ASSERT_EQ(convert("model/quad.obj scene.xml").code, 0);
  const std::string before = read(dir_ / "scene.xml");
  fs::create_directory(dir_ / "sub");
  fs::create_symlink(dir_ / "scene.xml", dir_ / "link.xml");
  // The same path, another spelling of it, and a link to it. (Letter case folds only on
  // case-insensitive file systems; the check is the same inode test.)
  for (const char* out : {"scene.xml", "./sub/../scene.xml", "link.xml"}) {
    Outcome r = convert(std::string("scene.xml ") + out);
    EXPECT_EQ(r.code, 1) << out;
    EXPECT_EQ(lines(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("is the input file"), std::string::npos) << r.err;
    EXPECT_EQ(read(dir_ / "scene.xml"), before) << out;
  }
  // An OBJ export writes its MTL too: it must not be the input either.
  Outcome r = convert("model/quad.mtl model/quad.obj");
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_EQ(lines(r.err), 1) << r.err;
}

TEST_F(ConvertFiles, MissingMaterialLibraryWarnsOnceNamingIt) {
  write("quad.obj", std::string(kQuadObj).replace(7, 8, "gone.mtl"));
  Outcome r = convert("quad.obj quad.xml");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("material library 'gone.mtl'"), std::string::npos) << r.err;
  size_t first = r.err.find("gone.mtl");
  EXPECT_EQ(r.err.find("gone.mtl", r.err.find('\n', first)), std::string::npos) << r.err;
}

// One scene with a feature of every kind the other formats may not carry.
const char* kFeatureScene = R"(<Scene>
  <Cameras><Camera id="1">
    <Position>0 0 5</Position><Gaze>0 0 -1</Gaze><Up>0 1 0</Up>
    <NearPlane>-1 1 -1 1</NearPlane><NearDistance>2</NearDistance>
    <ImageResolution>8 8</ImageResolution><NumSamples>1</NumSamples>
    <ImageName>f.exr</ImageName>
    <Tonemap><TMO>Photographic</TMO><TMOOptions>0.18 1</TMOOptions></Tonemap>
    <Renderer>PathTracing</Renderer><RendererParams>NextEventEstimation</RendererParams>
  </Camera></Cameras>
  <Lights><DirectionalLight id="1"><Direction>0 0 -1</Direction>
    <Radiance>1 1 1</Radiance></DirectionalLight></Lights>
  <BRDFs><ModifiedPhong id="1" normalized="true"><Exponent>50</Exponent></ModifiedPhong></BRDFs>
  <Materials><Material id="1" BRDF="1"><DiffuseReflectance>0.5 0.5 0.5</DiffuseReflectance>
    </Material></Materials>
  <Textures><Images><Image id="1">tex.png</Image></Images>
    <TextureMap id="1" type="image"><ImageId>1</ImageId><DecalMode>blend_kd</DecalMode>
    </TextureMap>
    <TextureMap id="2" type="perlin"><DecalMode>replace_kd</DecalMode></TextureMap>
  </Textures>
  <VertexData>-1 -1 0 1 -1 0 1 1 0 0 0 -1</VertexData>
  <TexCoordData>0 1 1 1 1 0 0 0</TexCoordData>
  <Objects>
    <LightMesh id="1"><Material>1</Material><Radiance>5 5 5</Radiance>
      <Faces>1 2 3</Faces></LightMesh>
    <Mesh id="2"><Material>1</Material><Textures>1</Textures><Faces>1 2 3</Faces></Mesh>
    <LightSphere id="3"><Material>1</Material><Textures>2</Textures><Center>4</Center>
      <Radius>0.2</Radius><Radiance>2 2 2</Radiance></LightSphere>
  </Objects>
</Scene>)";

bool has_line(const std::string& err, const std::string& a, const std::string& b = "") {
  size_t at = 0;
  while ((at = err.find(a, at)) != std::string::npos) {
    size_t start = err.rfind('\n', at), end = err.find('\n', at);
    std::string line = err.substr(start == std::string::npos ? 0 : start, end - start);
    if (line.find(b) != std::string::npos) return true;
    ++at;
  }
  return false;
}

TEST_F(ConvertFiles, EveryFeatureAFormatDropsIsNamedInAWarning) {
  write("f.xml", kFeatureScene);
  Outcome obj = convert("f.xml f.obj");
  ASSERT_EQ(obj.code, 0) << obj.err;
  EXPECT_TRUE(has_line(obj.err, "LightMesh/LightSphere", "Radiance lost")) << obj.err;
  EXPECT_TRUE(has_line(obj.err, "Tonemap")) << obj.err;
  EXPECT_TRUE(has_line(obj.err, "Renderer PathTracing")) << obj.err;
  EXPECT_TRUE(has_line(obj.err, "BRDF")) << obj.err;
  EXPECT_TRUE(has_line(obj.err, "blend_kd")) << obj.err;
  EXPECT_TRUE(has_line(obj.err, "perlin")) << obj.err;
  EXPECT_TRUE(has_line(obj.err, "DirectionalLight")) << obj.err;
  Outcome pbrt = convert("f.xml f.pbrt");
  ASSERT_EQ(pbrt.code, 0) << pbrt.err;
  EXPECT_TRUE(has_line(pbrt.err, "Tonemap")) << pbrt.err;
  EXPECT_TRUE(has_line(pbrt.err, "RendererParams")) << pbrt.err;
  EXPECT_TRUE(has_line(pbrt.err, "BRDF")) << pbrt.err;
  EXPECT_TRUE(has_line(pbrt.err, "image TextureMap")) << pbrt.err;
  EXPECT_TRUE(has_line(pbrt.err, "perlin")) << pbrt.err;
  EXPECT_NE(read(dir_ / "f.pbrt").find("LightSource \"distant\""), std::string::npos);
  // pbrt carries object lights as area lights on their shapes.
  EXPECT_NE(read(dir_ / "f.pbrt").find("AreaLightSource \"diffuse\" \"rgb L\" [ 5 5 5 ]"),
            std::string::npos);
  // glTF keeps all of it in extras, XML is the course's own format: no warning.
  for (const char* out : {"f.glb", "f2.xml"}) {
    Outcome r = convert(std::string("f.xml ") + out);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(lines(r.err), 0) << out << ": " << r.err;
  }
}

// The glTF round trip of hw6's path-traced Cornell box keeps its LightMesh, the Renderer
// and RendererParams and the Tonemap of all eight cameras, and the BRDFs.
TEST_F(ConvertFiles, Hw6GltfRoundTripKeepsObjectLightsRendererAndTonemap) {
  const fs::path scene =
      fs::path(RT_SHARED_SCENES_DIR) / "hw6/pathTracing/cornellbox_jaroslav_path_glass.xml";
  if (!fs::exists(scene)) GTEST_SKIP() << scene << " is not present (../shared/scenes)";
  ASSERT_EQ(convert(scene.string() + " box.glb").code, 0);
  Outcome r = convert("box.glb box.xml");
  ASSERT_EQ(r.code, 0) << r.err;
  rt::SceneDesc a = rt::load_scene(scene.string()), b = rt::load_scene((dir_ / "box.xml").string());
  ASSERT_EQ(a.objects.size(), b.objects.size());
  int emitters = 0;
  for (size_t i = 0; i < a.objects.size(); ++i) {
    EXPECT_EQ(a.objects[i].emits, b.objects[i].emits) << i;
    EXPECT_EQ(a.objects[i].radiance.x, b.objects[i].radiance.x) << i;
    emitters += b.objects[i].emits;
  }
  EXPECT_EQ(emitters, 1);
  ASSERT_EQ(a.cameras.size(), b.cameras.size());
  for (size_t i = 0; i < a.cameras.size(); ++i) {
    EXPECT_TRUE(b.cameras[i].tonemap && b.cameras[i].path_tracing) << i;
    EXPECT_EQ(a.cameras[i].path_flags, b.cameras[i].path_flags) << i;
    EXPECT_EQ(a.cameras[i].tonemap_params.burn_percent, b.cameras[i].tonemap_params.burn_percent);
    EXPECT_EQ(a.cameras[i].image_name, b.cameras[i].image_name);
  }
  ASSERT_EQ(a.materials.size(), b.materials.size());
  for (size_t i = 0; i < a.materials.size(); ++i) {
    EXPECT_EQ(a.materials[i].brdf, b.materials[i].brdf) << i;
    EXPECT_EQ(a.materials[i].brdf_flags, b.materials[i].brdf_flags) << i;
    EXPECT_EQ(a.materials[i].phong_exponent, b.materials[i].phong_exponent) << i;
  }
}

// Outcome in an empty folder with input and output elsewhere, a conversion writes nothing
// there; the meshes above 100 triangles go to OUT_files beside the output.
TEST_F(ConvertFiles, NothingIsWrittenIntoTheCurrentFolder) {
  std::string grid;  // 11 x 11 quads: 242 triangles, written as PLY.
  for (int y = 0; y <= 11; ++y)
    for (int x = 0; x <= 11; ++x)
      grid += "v " + std::to_string(x) + " " + std::to_string(y) + " 0\n";
  for (int y = 0; y < 11; ++y)
    for (int x = 0; x < 11; ++x) {
      int a = y * 12 + x + 1;
      grid += "f " + std::to_string(a) + " " + std::to_string(a + 1) + " " +
              std::to_string(a + 13) + " " + std::to_string(a + 12) + "\n";
    }
  write("in/grid.obj", grid);
  fs::create_directories(dir_ / "empty");
  Outcome r = convert("../in/grid.obj ../out/grid.xml --width 32", dir_ / "empty");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(fs::is_empty(dir_ / "empty"));
  std::vector<std::string> written;
  for (const auto& e : fs::recursive_directory_iterator(dir_ / "out"))
    written.push_back(fs::relative(e.path(), dir_ / "out").string());
  std::sort(written.begin(), written.end());
  ASSERT_EQ(written.size(), 3u);
  EXPECT_EQ(written[0], "grid.xml");
  EXPECT_EQ(written[1], "grid_files");
  EXPECT_EQ(written[2].rfind("grid_files/mesh1", 0), 0u) << written[2];
  // The same from a scene: an export to every format writes only what was asked.
  for (const char* out : {"../out/g.glb", "../out/g.pbrt", "../out/g.obj", "../out/g2.xml"})
    ASSERT_EQ(convert(std::string("../out/grid.xml ") + out, dir_ / "empty").code, 0) << out;
  EXPECT_TRUE(fs::is_empty(dir_ / "empty"));
  // The scene renders from there, its PLY file found beside it.
  EXPECT_EQ(render("out/grid.xml", "grid.png").width, 32);
}

}  // namespace
