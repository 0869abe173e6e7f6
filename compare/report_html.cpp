#include "report_html.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "colormap.h"
#include "embed.h"
#include "io/file_util.h"

namespace cmp {
namespace {

constexpr int kTileDisplay = 128;  // Pixels an enlarged tile is at least wide.

const char* kStyle = R"(<style>
body { font-family: sans-serif; margin: 1.5em; color: #222; }
.verdict { font-size: 1.3em; padding: 0.6em 0.9em; border-radius: 6px; }
.identical, .within-noise { background: #d8f0d8; } .biased { background: #f6d5d5; }
.differ { background: #f3ead0; }
.row { display: grid; grid-template-columns: repeat(auto-fit, minmax(280px, 1fr)); gap: 1em; }
figure { margin: 0; } figcaption { font-size: 0.9em; margin-top: 0.3em; }
img.view { width: 100%; image-rendering: pixelated; display: block; }
.boxed { position: relative; }
.box { position: absolute; border: 2px solid #fff; outline: 1px solid #000;
  box-sizing: border-box; }
.box span { position: absolute; top: -1.3em; left: 0; color: #000; font-weight: bold;
  font-size: 0.8em; background: rgba(255,255,255,0.8); padding: 0 2px; }
img.bar { width: 200px; height: 12px; vertical-align: middle; image-rendering: pixelated; }
table { border-collapse: collapse; } td, th { padding: 0.25em 0.6em; text-align: left;
  vertical-align: top; border-bottom: 1px solid #ddd; }
img.tile { image-rendering: pixelated; }
.rejected { color: #b00000; font-weight: bold; }
</style>
)";

// Counts the images the browser decoded; tests/compare/report_browser.sh reads the line.
const char* kLoadCheck = R"(<p id="load-check">images loaded: not checked</p>
<script>
window.addEventListener('load', function () {
  var imgs = document.images, ok = 0;
  for (var i = 0; i < imgs.length; ++i) if (imgs[i].complete && imgs[i].naturalWidth > 0) ++ok;
  document.getElementById('load-check').textContent =
      'images loaded: ' + ok + ' of ' + imgs.length;
});
</script>
)";

std::string num(const char* format, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

std::string img(const std::string& cls, const std::string& id, const rt::Image8& image,
                const std::string& alt) {
  return "<img class=\"" + cls + "\" id=\"" + id + "\" alt=\"" + html_escape(alt) + "\" src=\"" +
         png_data_uri(image) + "\">";
}

const char* finding_class(Finding f) {
  switch (f) {
    case Finding::kIdentical:
      return "identical";
    case Finding::kWithinNoise:
      return "within-noise";
    case Finding::kBiased:
      return "biased";
    case Finding::kDiffer:
      return "differ";
  }
  return "differ";
}

std::string describe(const char* label, const Side& s) {
  std::string row = std::string("<tr><th>") + label + "</th><td>" + html_escape(s.path) +
                    "</td><td>" + std::to_string(s.image.width) + "x" +
                    std::to_string(s.image.height) + "</td><td>";
  if (s.has_moments)
    row += "moments " + html_escape(s.moments_path) + ": " + std::to_string(s.moments.info.spp) +
           " spp, seed " + std::to_string(s.moments.info.seed) + ", " +
           html_escape(s.moments.info.device);
  else
    row += "no moments";
  return row + "</td></tr>\n";
}

// The tiles' smallest p through the colour map (1 at the rejection level), red where
// rejected, grey where not tested; at the image's size, so the boxes of the worst tiles
// fall on it as on the difference map.
rt::Image8 significance_map(const Analysis& r) {
  rt::Image8 m;
  m.width = r.width;
  m.height = r.height;
  m.rgb.assign(static_cast<size_t>(m.width) * m.height * 3, 96);
  double level = std::log10(std::clamp(r.verdict.sidak_level, 1e-300, 0.5));
  for (const TileFigures& t : r.tiles) {
    uint8_t px[3] = {96, 96, 96};
    if (t.rejected) {
      px[0] = 255, px[1] = px[2] = 0;
    } else if (t.tested) {
      viridis(t.p > 0 ? std::log10(t.p) / level : 1.0, px);
    }
    for (int y = t.y; y < t.y + t.h; ++y)
      for (int x = t.x; x < t.x + t.w; ++x)
        std::copy(px, px + 3, &m.rgb[(static_cast<size_t>(y) * m.width + x) * 3]);
  }
  return m;
}

std::string boxes(const Analysis& r) {
  std::string s;
  for (size_t k = 0; k < r.worst.size(); ++k) {
    const TileFigures& t = r.tiles[r.worst[k]];
    s += "<div class=\"box\" style=\"left:" + num("%.4f", 100.0 * t.x / r.width) +
         "%;top:" + num("%.4f", 100.0 * t.y / r.height) +
         "%;width:" + num("%.4f", 100.0 * t.w / r.width) +
         "%;height:" + num("%.4f", 100.0 * t.h / r.height) + "%\"><span>" + std::to_string(k + 1) +
         "</span></div>";
  }
  return s;
}

std::string tile_figures(const TileFigures& t, bool moments) {
  std::string s =
      "mean |B - A| " + num("%.3g", t.mean_abs) + " levels, largest " + std::to_string(t.max_abs);
  const char* unit = moments ? " (mean radiance)" : " (mean levels)";
  s += "<br>A" + std::string(unit) + ": ";
  for (int c = 0; c < 3; ++c) s += num(c ? ", %.4g" : "%.4g", t.mean_a[c]);
  s += "<br>B: ";
  for (int c = 0; c < 3; ++c) s += num(c ? ", %.4g" : "%.4g", t.mean_b[c]);
  s += "<br>B - A: ";
  for (int c = 0; c < 3; ++c) s += num(c ? ", %+.3g" : "%+.3g", t.mean_b[c] - t.mean_a[c]);
  if (t.tested)
    s += std::string("<br><span class=\"") + (t.rejected ? "rejected" : "") + "\">smallest p " +
         num("%.3g", t.p) + (t.rejected ? ": rejected" : "") + "</span>";
  return s;
}

std::string worst_table(const Side& a, const Side& b, const Analysis& r, const rt::Image8& dmap) {
  if (r.worst.empty()) return "<p>No tile differs.</p>\n";
  int zoom = std::max(1, kTileDisplay / r.tile);
  std::string s =
      "<table class=\"tiles\"><tr><th>#</th><th>tile (pixels)</th><th>A</th>"
      "<th>B</th><th>|B - A|</th><th>figures</th></tr>\n";
  for (size_t k = 0; k < r.worst.size(); ++k) {
    const TileFigures& t = r.tiles[r.worst[k]];
    std::string n = std::to_string(k + 1), name = tile_name(t);
    auto cell = [&](const rt::Image8& im, const char* which) {
      return "<td>" +
             img("tile", std::string("tile-") + which + "-" + n,
                 enlarge(crop(im, t.x, t.y, t.w, t.h), zoom), std::string(which) + " " + name) +
             "</td>";
    };
    s += "<tr><td>" + n + "</td><td>" + name + "</td>" + cell(a.image, "a") + cell(b.image, "b") +
         cell(dmap, "diff") + "<td>" + tile_figures(t, a.has_moments && b.has_moments) +
         "</td></tr>\n";
  }
  return s + "</table>\n";
}

}  // namespace

std::string report_html(const Side& a, const Side& b, const Analysis& r, const ReportOptions& o) {
  rt::Image8 dmap = colour_map(r.width, r.height, r.pixel_diff, r.scale);
  std::string h =
      "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n<title>"
      "compare report: " +
      html_escape(a.path) + " vs " + html_escape(b.path) + "</title>\n" + kStyle +
      "</head><body>\n<h1>compare report</h1>\n";
  h += std::string("<p id=\"verdict\" class=\"verdict ") + finding_class(r.finding) +
       "\" data-finding=\"" + finding_class(r.finding) + "\">" + html_escape(r.words) + "</p>\n";
  h += "<table class=\"inputs\">\n" + describe("A", a) + describe("B", b) + "</table>\n";
  h += "<p>" + std::to_string(r.width) + "x" + std::to_string(r.height) +
       " px; 8-bit images: " + "MAE " + num("%.4g", r.diff.mae) + ", RMSE " +
       num("%.4g", r.diff.rmse) + ", PSNR " + num("%.2f dB", r.diff.psnr) +
       ", largest difference " + std::to_string(r.diff.max_abs) + ", pixels differing " +
       num("%.3g %%", 100 * (1 - r.diff.frac_identical)) + ", by more than 8 " +
       num("%.3g %%", 100 * r.diff.frac_over) + ".";
  if (!r.test.empty())
    h += " Test: " + r.test + " on " + std::to_string(r.tile) + "x" + std::to_string(r.tile) +
         " tiles, " + std::to_string(r.verdict.tests) + " tests, " +
         std::to_string(r.verdict.rejections) + " rejected (per-test level " +
         num("%.3g", r.verdict.sidak_level) + ", alpha " + num("%g", o.family.alpha) + ").";
  h += "</p>\n<div class=\"row\">\n";
  h += "<figure>" + img("view", "img-a", a.image, "A") + "<figcaption>A: " + html_escape(a.path) +
       "</figcaption></figure>\n";
  h += "<figure>" + img("view", "img-b", b.image, "B") + "<figcaption>B: " + html_escape(b.path) +
       "</figcaption></figure>\n";
  h += "<figure><div class=\"boxed\">" + img("view", "img-diff", dmap, "difference map") +
       boxes(r) + "</div><figcaption>|B - A|, largest channel: 0 " +
       img("bar", "bar-diff", colour_bar(256, 1), "colour bar") + " " + num("%.0f", r.scale) +
       " levels and above (viridis); numbered boxes: the worst tiles" + "</figcaption></figure>\n";
  if (!r.test.empty())
    h += "<figure><div class=\"boxed\">" +
         img("view", "img-significance", significance_map(r), "significance map") + boxes(r) +
         "</div><figcaption>smallest p per tile (" + r.test + "): p = 1 " +
         img("bar", "bar-p", colour_bar(256, 1), "colour bar") +
         " the rejection level; red rejected, grey not tested</figcaption></figure>\n";
  h += "</div>\n<h2>Worst tiles</h2>\n" + worst_table(a, b, r, dmap);
  return h + kLoadCheck + "</body></html>\n";
}

std::string report_path(const std::string& out) {
  std::error_code ec;
  bool dir = std::filesystem::is_directory(out, ec) || (!out.empty() && out.back() == '/');
  if (!dir) return out;
  std::filesystem::create_directories(out, ec);
  if (ec) throw std::runtime_error(out + ": cannot create the directory: " + ec.message());
  return (std::filesystem::path(out) / "report.html").string();
}

void write_report(const std::string& path, const std::string& html) {
  int err = rt::write_file_atomic(path, html.data(), html.size());
  if (err) throw std::runtime_error(path + ": cannot write the report: " + rt::errno_text(err));
}

}  // namespace cmp
