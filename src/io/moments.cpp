#include "io/moments.h"
#include "io/partial_mark.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfStringAttribute.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <stdexcept>

#include "io/exr_file.h"

namespace rt {
namespace {

constexpr int kFormatVersion = 1;
const char* const kMeanNames[3] = {"R", "G", "B"};
const char* const kVarNames[3] = {"var.R", "var.G", "var.B"};
const char* const kNormalNames[3] = {"first.N.X", "first.N.Y", "first.N.Z"};

// Slices of one interleaved or planar array; OpenEXR addresses pixel (x, y) as
// base + x * xstride + y * ystride, and the data window may not start at (0, 0).
Imf::Slice slice(Imf::PixelType type, const void* data, size_t elem, int per_pixel, int width,
                 const Imath::Box2i& dw) {
  size_t xs = elem * per_pixel, ys = xs * width;
  char* base = const_cast<char*>(static_cast<const char*>(data)) -
               static_cast<ptrdiff_t>(dw.min.x) * xs - static_cast<ptrdiff_t>(dw.min.y) * ys;
  return Imf::Slice(type, base, xs, ys);
}

// The frame buffer over every channel of `m`, used for writing and (after resizing) reading.
Imf::FrameBuffer frame_buffer(MomentImage& m, std::vector<uint32_t>& inst,
                              std::vector<uint32_t>& prim, const Imath::Box2i& dw) {
  Imf::FrameBuffer fb;
  for (int c = 0; c < 3; ++c) {
    fb.insert(kMeanNames[c], slice(Imf::FLOAT, m.mean.data() + c, 4, 3, m.width, dw));
    fb.insert(kVarNames[c], slice(Imf::FLOAT, m.var.data() + c, 4, 3, m.width, dw));
    fb.insert(kNormalNames[c], slice(Imf::FLOAT, m.normal.data() + c, 4, 3, m.width, dw));
  }
  fb.insert("n", slice(Imf::UINT, m.count.data(), 4, 1, m.width, dw));
  fb.insert("first.t", slice(Imf::FLOAT, m.first_t.data(), 4, 1, m.width, dw));
  fb.insert("first.instance", slice(Imf::UINT, inst.data(), 4, 1, m.width, dw));
  fb.insert("first.primitive", slice(Imf::UINT, prim.data(), 4, 1, m.width, dw));
  return fb;
}

void resize(MomentImage& m) {
  size_t n = m.pixels();
  m.mean.assign(n * 3, 0.0f);
  m.var.assign(n * 3, 0.0f);
  m.normal.assign(n * 3, 0.0f);
  m.count.assign(n, 0);
  m.first_t.assign(n, 0.0f);
  m.instance.assign(n, -1);
  m.primitive.assign(n, -1);
}

}  // namespace

MomentImage moments_from_render(const RenderResult& r, const MomentInfo& info) {
  MomentImage m;
  m.width = r.width;
  m.height = r.height;
  m.info = info;
  resize(m);
  for (size_t i = 0; i < m.pixels(); ++i) {
    const PixelEstimate e = estimate_pixel(r.accum[i]);
    for (int c = 0; c < 3; ++c) {
      m.mean[i * 3 + c] = static_cast<float>(e.mean[c]);
      m.var[i * 3 + c] = static_cast<float>(e.var[c]);
    }
    m.count[i] = static_cast<uint32_t>(e.n);
    if (i < r.primary.size()) {
      const PrimaryInfo& p = r.primary[i];
      bool hit = p.instance >= 0;
      m.first_t[i] = hit ? p.t : std::numeric_limits<float>::infinity();
      m.instance[i] = hit ? p.instance : -1;
      m.primitive[i] = hit ? p.primitive : -1;
      m.normal[i * 3 + 0] = hit ? p.normal.x : 0.0f;
      m.normal[i * 3 + 1] = hit ? p.normal.y : 0.0f;
      m.normal[i * 3 + 2] = hit ? p.normal.z : 0.0f;
    }
  }
  return m;
}

std::string moments_path_for(const std::string& png_path) {
  std::filesystem::path p(png_path);
  p.replace_extension(".moments.exr");
  return p.string();
}

void write_moments(const std::string& path, const MomentImage& m) {
  try {
    if (m.width <= 0 || m.height <= 0 || m.mean.size() != m.pixels() * 3)
      throw std::runtime_error("inconsistent image");
    Imf::Header h(m.width, m.height);
    h.compression() = Imf::ZIP_COMPRESSION;
    for (int c = 0; c < 3; ++c) {
      h.channels().insert(kMeanNames[c], Imf::Channel(Imf::FLOAT));
      h.channels().insert(kVarNames[c], Imf::Channel(Imf::FLOAT));
      h.channels().insert(kNormalNames[c], Imf::Channel(Imf::FLOAT));
    }
    h.channels().insert("n", Imf::Channel(Imf::UINT));
    h.channels().insert("first.t", Imf::Channel(Imf::FLOAT));
    h.channels().insert("first.instance", Imf::Channel(Imf::UINT));
    h.channels().insert("first.primitive", Imf::Channel(Imf::UINT));
    h.insert("rt.moments", Imf::IntAttribute(kFormatVersion));
    h.insert("rt.seed", Imf::IntAttribute(static_cast<int>(m.info.seed)));
    h.insert("rt.spp", Imf::IntAttribute(m.info.spp));
    h.insert("rt.filter", Imf::StringAttribute(m.info.filter));
    h.insert("rt.device", Imf::StringAttribute(m.info.device));
    h.insert("rt.scene", Imf::StringAttribute(m.info.scene));
    h.insert("rt.camera", Imf::IntAttribute(m.info.camera));
    if (!m.info.samples_mark.empty())
      h.insert(kSamplesMarkKey, Imf::StringAttribute(m.info.samples_mark));
    MomentImage copy = m;  // The frame buffer wants mutable storage.
    std::vector<uint32_t> inst(m.instance.begin(), m.instance.end());
    std::vector<uint32_t> prim(m.primitive.begin(), m.primitive.end());
    write_exr_atomic(path, h, frame_buffer(copy, inst, prim, h.dataWindow()), m.height);
  } catch (const std::exception& e) {
    throw std::runtime_error(path + ": cannot write moments: " + e.what());
  }
}

MomentImage read_moments(const std::string& path) {
  try {
    Imf::InputFile in(path.c_str());
    const Imf::Header& h = in.header();
    const auto* version = h.findTypedAttribute<Imf::IntAttribute>("rt.moments");
    if (!version) throw std::runtime_error("not a moment file (no rt.moments attribute)");
    if (version->value() != kFormatVersion)
      throw std::runtime_error("format version " + std::to_string(version->value()) +
                               " (this build reads " + std::to_string(kFormatVersion) + ")");
    for (const char* c : {"R", "G", "B", "var.R", "var.G", "var.B", "n", "first.t",
                          "first.instance", "first.primitive", "first.N.X", "first.N.Y",
                          "first.N.Z"})
      if (!h.channels().findChannel(c)) throw std::runtime_error(std::string("no channel ") + c);
    MomentImage m;
    Imath::Box2i dw = h.dataWindow();
    m.width = dw.max.x - dw.min.x + 1;
    m.height = dw.max.y - dw.min.y + 1;
    resize(m);
    if (const auto* a = h.findTypedAttribute<Imf::IntAttribute>("rt.seed"))
      m.info.seed = static_cast<uint32_t>(a->value());
    if (const auto* a = h.findTypedAttribute<Imf::IntAttribute>("rt.spp")) m.info.spp = a->value();
    if (const auto* a = h.findTypedAttribute<Imf::IntAttribute>("rt.camera"))
      m.info.camera = a->value();
    if (const auto* a = h.findTypedAttribute<Imf::StringAttribute>("rt.filter"))
      m.info.filter = a->value();
    if (const auto* a = h.findTypedAttribute<Imf::StringAttribute>("rt.device"))
      m.info.device = a->value();
    if (const auto* a = h.findTypedAttribute<Imf::StringAttribute>("rt.scene"))
      m.info.scene = a->value();
    std::vector<uint32_t> inst(m.pixels()), prim(m.pixels());
    in.setFrameBuffer(frame_buffer(m, inst, prim, dw));
    in.readPixels(dw.min.y, dw.max.y);
    for (size_t i = 0; i < m.pixels(); ++i) {
      m.instance[i] = static_cast<int32_t>(inst[i]);
      m.primitive[i] = static_cast<int32_t>(prim[i]);
    }
    return m;
  } catch (const std::exception& e) {
    throw std::runtime_error(path + ": cannot read moments: " + e.what());
  }
}

}  // namespace rt
