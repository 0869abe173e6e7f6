#include "reference_criterion.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace cmp {
namespace {

bool parse_number(const std::string& s, double* out) {
  char* end = nullptr;
  *out = std::strtod(s.c_str(), &end);
  return !s.empty() && *end == '\0' && std::isfinite(*out) && *out >= 0;
}

}  // namespace

std::string criterion_help() {
  char buf[600];
  std::snprintf(buf, sizeof buf,
                "hw12 (one sample per pixel, deterministic): MAE <= %g levels, <= %g %% of pixels "
                "off by more than 8, at least P %% of pixels identical (default %g); hw3 (noisy): "
                "after a 4x4 box downsample MAE <= %g, full-resolution MAE <= %g, |mean bias| <= "
                "B (default %g); block (a noisy reference): after a 4x4 box downsample MAE <= M "
                "(default %g), |mean bias| <= %g",
                kHw12Mae, 100 * kHw12Over8, kHw12Identical, kHw3DownMae, kHw3Mae, kHw3Bias,
                kBlockDownMae, kBlockBias);
  return buf;
}

ReferenceResult check_reference(const rt::Image8& render, const rt::Image8& reference,
                                const ReferenceCriterion& c, bool double_precision) {
  ReferenceResult r;
  r.full = rt::diff_images(reference, render, 8);
  r.down = rt::diff_images(rt::downsample(reference, 4), rt::downsample(render, 4), 8);
  // Signed mean of render minus reference: a conversion one level off shows here first.
  for (size_t i = 0; i < render.rgb.size(); ++i) r.bias += render.rgb[i] - reference.rgb[i];
  r.bias /= std::max<size_t>(1, render.rgb.size());
  bool hw3 = c.kind == "hw3", by_block = c.kind == "block";
  r.min_identical = c.min_identical > 0 ? c.min_identical : hw3 || by_block ? 0 : kHw12Identical;
  if (double_precision && c.double_min_identical > 0) r.min_identical = c.double_min_identical;
  bool ok = hw3 ? (r.down.mae <= kHw3DownMae && r.full.mae <= kHw3Mae &&
                   std::abs(r.bias) <= (c.max_bias >= 0 ? c.max_bias : kHw3Bias))
                : (r.full.mae <= kHw12Mae && r.full.frac_over <= kHw12Over8);
  if (by_block)
    ok = r.down.mae <= (c.max_block_mae >= 0 ? c.max_block_mae : kBlockDownMae) &&
         std::abs(r.bias) <= (c.max_bias >= 0 ? c.max_bias : kBlockBias);
  r.pass = ok && 100 * r.full.frac_identical >= r.min_identical;
  return r;
}

bool parse_criterion(const std::string& field, ReferenceCriterion* c, std::string* error) {
  *c = ReferenceCriterion{};
  std::string head = field.substr(0, field.find(','));
  for (size_t at = head.size(); at < field.size();) {
    size_t next = field.find(',', at + 1);
    std::string part = field.substr(at + 1, next == std::string::npos ? next : next - at - 1);
    if (part.compare(0, 7, "double:") != 0 ||
        !parse_number(part.substr(7), &c->double_min_identical)) {
      *error = "criterion '" + field + "': unknown part '" + part + "' (expected double:P)";
      return false;
    }
    at = next == std::string::npos ? field.size() : next;
  }
  size_t colon = head.find(':');
  c->kind = head.substr(0, colon);
  if (c->kind != "hw12" && c->kind != "hw3" && c->kind != "block") {
    *error = "criterion '" + field + "': unknown kind '" + c->kind + "' (hw12, hw3 or block)";
    return false;
  }
  if (colon == std::string::npos) return true;
  double limit = 0;
  if (!parse_number(head.substr(colon + 1), &limit)) {
    *error = "criterion '" + field + "': limit '" + head.substr(colon + 1) + "' is not a number";
    return false;
  }
  (c->kind == "hw3"     ? c->max_bias
   : c->kind == "block" ? c->max_block_mae
                        : c->min_identical) = limit;
  return true;
}

bool find_course_criterion(const std::string& list, const std::string& reference, std::string* name,
                           std::string* field) {
  std::ifstream in(list);
  if (!in) throw std::runtime_error(list + ": cannot read the list of course scenes");
  std::error_code ec;
  std::string ref = std::filesystem::weakly_canonical(reference, ec).generic_string();
  if (ec) ref = reference;
  for (std::string text; std::getline(in, text);) {
    std::istringstream fields(text);
    std::string n, scene, path, criterion;
    if (text.empty() || text[0] == '#' || !(fields >> n >> scene >> path >> criterion)) continue;
    bool match = ref == path || (ref.size() > path.size() &&
                                 ref.compare(ref.size() - path.size(), path.size(), path) == 0 &&
                                 ref[ref.size() - path.size() - 1] == '/');
    if (!match) continue;
    *name = n;
    *field = criterion;
    return true;
  }
  return false;
}

void print_reference_result(const std::string& label, const std::string& detail,
                            const ReferenceResult& r, const ReferenceCriterion& c, long pixels) {
  std::printf(
      "%s: %s: MAE %.3f, over 8: %.3f %%, max %d, identical %.3f %% (%ld differ), bias %+.3f | "
      "4x4 downsampled: MAE %.3f, over 8: %.3f %%\n",
      label.c_str(), detail.c_str(), r.full.mae, 100 * r.full.frac_over, r.full.max_abs,
      100 * r.full.frac_identical, std::lround((1 - r.full.frac_identical) * pixels), r.bias,
      r.down.mae, 100 * r.down.frac_over);
  std::printf("%s (criterion %s)\n", r.pass ? "PASS" : "FAIL", c.kind.c_str());
}

}  // namespace cmp
