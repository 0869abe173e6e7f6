// Writes a benchmark scene: a bumpy plane of about N triangles (a height field of sines on
// a square grid, binary PLY) seen from above at an angle, with one point light.
//   bumpy_plane TRIANGLES OUT_DIR    (writes OUT_DIR/bumpy.xml and OUT_DIR/bumpy.ply)
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: bumpy_plane TRIANGLES OUT_DIR\n");
    return 2;
  }
  long tris = std::atol(argv[1]);
  std::string dir = argv[2];
  int n = std::max(1, static_cast<int>(std::lround(std::sqrt(tris / 2.0))));  // Cells per side.
  std::string ply = dir + "/bumpy.ply", xml = dir + "/bumpy.xml";
  FILE* f = std::fopen(ply.c_str(), "wb");
  if (!f) {
    std::fprintf(stderr, "bumpy_plane: cannot write %s\n", ply.c_str());
    return 1;
  }
  long verts = static_cast<long>(n + 1) * (n + 1), faces = 2L * n * n;
  std::fprintf(f,
               "ply\nformat binary_little_endian 1.0\nelement vertex %ld\nproperty float x\n"
               "property float y\nproperty float z\nelement face %ld\n"
               "property list uchar int vertex_indices\nend_header\n",
               verts, faces);
  std::vector<float> row(3 * (n + 1));
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      float x = -1.0f + 2.0f * i / n, y = -1.0f + 2.0f * j / n;
      row[3 * i] = x;
      row[3 * i + 1] = y;
      row[3 * i + 2] = 0.05f * std::sin(23.0f * x) * std::cos(31.0f * y) +
                       0.02f * std::sin(97.0f * x + 53.0f * y);
    }
    std::fwrite(row.data(), sizeof(float), row.size(), f);
  }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      int32_t a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
      unsigned char three = 3;
      int32_t t0[3] = {a, b, d}, t1[3] = {a, d, c};
      std::fwrite(&three, 1, 1, f);
      std::fwrite(t0, 4, 3, f);
      std::fwrite(&three, 1, 1, f);
      std::fwrite(t1, 4, 3, f);
    }
  std::fclose(f);
  f = std::fopen(xml.c_str(), "w");
  if (!f) {
    std::fprintf(stderr, "bumpy_plane: cannot write %s\n", xml.c_str());
    return 1;
  }
  std::fprintf(f, R"(<Scene>
  <MaxRecursionDepth>1</MaxRecursionDepth>
  <BackgroundColor>0 0 0</BackgroundColor>
  <Cameras>
    <Camera id="1">
      <Position>0 -2.2 1.6</Position>
      <Gaze>0 1.1 -0.8</Gaze>
      <Up>0 0 1</Up>
      <NearPlane>-0.5 0.5 -0.5 0.5</NearPlane>
      <NearDistance>1</NearDistance>
      <ImageResolution>800 800</ImageResolution>
      <ImageName>bumpy.png</ImageName>
      <NumSamples>1</NumSamples>
    </Camera>
  </Cameras>
  <Lights>
    <AmbientLight>20 20 20</AmbientLight>
    <PointLight id="1">
      <Position>0.5 -1 3</Position>
      <Intensity>3000 3000 3000</Intensity>
    </PointLight>
  </Lights>
  <Materials>
    <Material id="1">
      <AmbientReflectance>1 1 1</AmbientReflectance>
      <DiffuseReflectance>0.6 0.6 0.6</DiffuseReflectance>
      <SpecularReflectance>0.3 0.3 0.3</SpecularReflectance>
      <PhongExponent>20</PhongExponent>
    </Material>
  </Materials>
  <VertexData>0 0 0</VertexData>
  <Objects>
    <Mesh id="1">
      <Material>1</Material>
      <Faces plyFile="bumpy.ply"/>
    </Mesh>
  </Objects>
</Scene>
)");
  std::fclose(f);
  return 0;
}
