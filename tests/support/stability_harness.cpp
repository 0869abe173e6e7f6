#include "support/stability_harness.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

#include "io/png_io.h"
#include "paired.h"
#include "welch.h"

namespace stab {

const char* Name(Dev d) { return rt::test::device_label(d); }

rt::FlatScene Flatten(const rt::SceneDesc& s, const rt::RenderOptions& o, int camera) {
  rt::FlatScene f = rt::prepare_scene(s, o);
  rt::prepare_camera(f, s, camera, o);
  return f;
}

namespace {

void Dump(const std::string& label, const rt::RenderResult& r) {
  const char* dir = std::getenv("RT_STAB_DUMP");
  if (!dir || !*dir) return;
  std::string name = label;
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '.') c = '_';
  rt::write_png(std::string(dir) + "/" + name + ".png", rt::to_8bit(r.width, r.height, r.rgb()));
}

}  // namespace

rt::RenderResult RenderOn(Dev d, const rt::FlatScene& f, const std::string& label) {
  std::string why;
  rt::RenderDevice* device = rt::test::shared_device(d, &why);
  if (!device) throw std::runtime_error("no OpenCL device: " + why);
  rt::RenderResult r = rt::test::render_on(*device, f);
  if (d == Dev::kCpu && !label.empty()) Dump(label, r);
  return r;
}

// No sample of the render was NaN or infinite, and every reconstructed value is finite.
void ExpectFinite(const rt::RenderResult& r, const std::string& label) {
  EXPECT_EQ(r.nonfinite(), 0u) << label << ": samples with NaN/Inf radiance";
  size_t bad = 0;
  for (float v : r.rgb()) bad += !std::isfinite(v);
  EXPECT_EQ(bad, 0u) << label << ": non-finite pixel values";
  for (const PrimaryInfo& p : r.primary)
    if (p.instance >= 0) {
      EXPECT_TRUE(std::isfinite(p.t) && std::isfinite(p.normal.x) && std::isfinite(p.normal.y) &&
                  std::isfinite(p.normal.z))
          << label << ": non-finite primary hit";
      break;
    }
}

rt::MomentImage Moments(const rt::RenderResult& r, const std::string& device) {
  rt::MomentInfo info;
  info.device = device;
  return rt::moments_from_render(r, info);
}

std::string Describe(const cmp::Verdict& v) {
  char buf[256];
  std::snprintf(buf, sizeof buf,
                "%s: %zu tests, %zu equal, %zu deterministic failures, %zu rejections, "
                "min p %.3g at (%d,%d)",
                v.pass ? "PASS" : "FAIL", v.tests, v.equal, v.deterministic, v.rejections, v.min_p,
                v.min_x, v.min_y);
  return buf;
}

namespace {

// The family-wise alpha of the compare tool's verdicts.
constexpr double kAlpha = 1e-3;

// The first few failing cells of a decided family, "(x,y)c:diff", for the failure message.
std::string FailingCells(const cmp::Family& f, size_t limit = 6) {
  std::string out;
  size_t n = 0;
  for (int cy = 0; cy < f.cells_y; ++cy)
    for (int cx = 0; cx < f.cells_x; ++cx) {
      const cmp::Cell& c = f.cells[static_cast<size_t>(cy) * f.cells_x + cx];
      for (int ch = 0; ch < 3; ++ch) {
        if (!c.rejected[ch] && c.status[ch] != cmp::CellStatus::kDeterministic) continue;
        if (n++ < limit) {
          char buf[64];
          std::snprintf(buf, sizeof buf, " (%d,%d)%c:%+.3g", cx * f.tile, cy * f.tile, "RGB"[ch],
                        c.diff[ch]);
          out += buf;
        }
      }
    }
  return out;
}

}  // namespace

std::string g_last_failing_cells;

cmp::Verdict WelchVerdict(const rt::MomentImage& a, const rt::MomentImage& b, int tile) {
  cmp::check_testable(a, b, false);
  cmp::WelchOptions wo;
  wo.tile = tile;
  cmp::Family f = cmp::welch_test(a, b, wo);
  cmp::FamilyOptions fo;
  fo.alpha = kAlpha;
  cmp::Verdict v = cmp::decide(f, fo);
  g_last_failing_cells = FailingCells(f);
  return v;
}

cmp::Verdict WelchVerdict(const rt::RenderResult& a, const rt::RenderResult& b, int tile) {
  return WelchVerdict(Moments(a, "a"), Moments(b, "b"), tile);
}

// CL against CPU on equal seeds. Both devices evaluate the same rounded operations in the
// same order, so the per-pixel means may differ only where a transcendental function
// (sqrt/exp/pow/sin/cos of the device library) rounds differently and a sample takes
// another branch. Required:
//  * the compare tool's paired sign test (8x8 tiles + whole image, alpha 1e-3) passes:
//    no systematic per-pixel difference;
//  * at most 1% of pixel-channels differ by more than 1e-4 relative (+1e-6 of the image
//    maximum), and with 1 spp none by more than 2% of the image maximum (with n spp one
//    diverging sample moves a pixel by up to its contrast / n).
// A render marked `statistical` amplifies those last-bit differences on purpose (a lens
// sample's sin/cos times an aperture of 1e6 moves ray origins by ~0.1): the per-value rule
// is replaced by the compare tool's Welch verdict (per pixel, alpha 1e-3), so the two
// devices must still render the same image in distribution.
void ExpectDevicesAgree(const Shots& cpu, const Shots& cl) {
  ASSERT_EQ(cpu.size(), cl.size());
  for (size_t k = 0; k < cpu.size(); ++k) {
    const rt::RenderResult& a = cpu[k].r;
    const rt::RenderResult& b = cl[k].r;
    const std::string& label = cpu[k].label;
    ASSERT_EQ(a.width, b.width) << label;
    ASSERT_EQ(a.height, b.height) << label;
    EXPECT_EQ(b.nonfinite(), 0u) << label << " (cl)";
    std::vector<float> ra = a.rgb(), rb = b.rgb();
    double vmax = 0;
    for (size_t i = 0; i < ra.size(); ++i)
      vmax = std::max({vmax, std::fabs(static_cast<double>(ra[i])), std::fabs(double(rb[i]))});
    size_t identical = 0, over = 0;
    double worst = 0;
    for (size_t i = 0; i < a.accum.size(); ++i)
      identical += std::memcmp(&a.accum[i].sum, &b.accum[i].sum, sizeof(float4)) == 0;
    for (size_t i = 0; i < ra.size(); ++i) {
      double d = std::fabs(static_cast<double>(ra[i]) - rb[i]);
      double tol =
          1e-4 * std::max(std::fabs(double(ra[i])), std::fabs(double(rb[i]))) + 1e-6 * vmax;
      over += d > tol;
      worst = std::max(worst, d);
    }
    rt::MomentImage ma = Moments(a, "cpu"), mb = Moments(b, "cl");
    cmp::PairedOptions po;
    cmp::Family f = cmp::paired_test(ma, mb, po);
    cmp::FamilyOptions fo;
    fo.alpha = kAlpha;
    fo.uniformity = false;  // Few tiles; ties dominate (bit-identical pixels).
    cmp::Verdict v = cmp::decide(f, fo);
    std::printf(
        "[ cl vs cpu ] %-44s %5.1f%% sums bit-identical, %zu/%zu values beyond tol, "
        "max |diff| %.3g of max %.3g, paired %s\n",
        label.c_str(), 100.0 * identical / a.accum.size(), over, ra.size(), worst, vmax,
        v.pass ? "PASS" : "FAIL");
    EXPECT_TRUE(v.pass) << label << ": paired test " << Describe(v);
    if (cpu[k].statistical) {
      cmp::Verdict w = WelchVerdict(ma, mb);
      std::printf("[ cl vs cpu ] %-44s statistical only: welch %s\n", label.c_str(),
                  Describe(w).c_str());
      EXPECT_TRUE(w.pass) << label << ": welch " << Describe(w);
      continue;
    }
    EXPECT_LE(over, ra.size() / 100) << label;
    // The sample count per pixel (1 spp: no divergence may go unnoticed).
    uint32_t n =
        static_cast<uint32_t>(a.accum.empty() ? 1 : a.accum[0].sum_sq.w + a.accum[0].nonfinite);
    if (n <= 1) {
      EXPECT_LE(worst, 0.02 * vmax + 1e-30) << label;
    }
  }
}

double Luminance(const std::vector<float>& rgb, size_t i) {
  return (rgb[i * 3] + rgb[i * 3 + 1] + rgb[i * 3 + 2]) / 3.0;
}

bool BitIdentical(const rt::RenderResult& a, const rt::RenderResult& b) {
  return a.accum.size() == b.accum.size() &&
         std::memcmp(a.accum.data(), b.accum.data(), a.accum.size() * sizeof(PixelAccum)) == 0;
}

}  // namespace stab
