// The criterion an image must meet against the course's official image: the one check the
// reference-image tests (tests/course/reference_check.cpp, which renders the scene) and
// `compare reference` (which reads an existing render) both apply.
//
// The 8-bit conversion truncates as the course's renderer does, so the deterministic
// images (hw1, hw2: one sample per pixel) are expected byte-identical but for a few
// pixels; the thresholds sit just outside what the CPU reference reaches on every course
// image (README, "Reference images").
#pragma once

#include <string>

#include "image_metrics.h"

namespace cmp {

// The thresholds, in 8-bit levels: what the CPU reference reaches on every course image,
// with a margin (README, "Reference images"). --help is written from them.
// hw12: deterministic images (one sample per pixel), compared pixel for pixel.
constexpr double kHw12Mae = 0.2, kHw12Over8 = 0.005, kHw12Identical = 99.9;
// hw3: noisy images, compared after a 4x4 box downsample, and by their mean bias.
constexpr double kHw3DownMae = 0.6, kHw3Mae = 2.0, kHw3Bias = 0.05;
// block: images whose reference is itself a noisy render (hw6 object lights, 100 spp),
// which two correct renders do not match pixel for pixel: only the 4x4-downsampled MAE
// and the mean bias are checked.
constexpr double kBlockDownMae = 2.0, kBlockBias = 0.3;

// kind: hw12 (deterministic, pixel for pixel), hw3 (noisy: after a 4x4 box downsample,
// and the mean bias) or block (a noisy reference: 4x4-downsampled MAE and mean bias).
// A limit below 0 (or min_identical 0) means the kind's own default.
struct ReferenceCriterion {
  std::string kind = "hw12";
  double min_identical = 0;         // Percent of byte-identical pixels.
  double double_min_identical = 0;  // The same for a render in double; 0: min_identical.
  double max_bias = -1;             // Largest |mean bias| (render minus reference), levels.
  double max_block_mae = -1;        // Largest 4x4-downsampled MAE of `block`.
};

struct ReferenceResult {
  rt::ImageDiff full, down;  // Pixel for pixel, and after a 4x4 box downsample.
  double bias = 0;           // Signed mean of render minus reference, levels.
  double min_identical = 0;  // The identical share required, percent (0: none).
  bool pass = false;
};

// The help line of --criterion, written from the thresholds.
std::string criterion_help();

// Checks `render` against `reference` (same size: throws std::invalid_argument otherwise).
// `double_precision`: the render computed in double (double_min_identical applies).
ReferenceResult check_reference(const rt::Image8& render, const rt::Image8& reference,
                                const ReferenceCriterion& c, bool double_precision);

// Reads a CRITERION field of tests/course/course_scenes.txt: KIND[:LIMIT][,double:P], where LIMIT
// is min_identical (hw12), max_bias (hw3) or max_block_mae (block). Returns false and sets
// *error on a malformed field.
bool parse_criterion(const std::string& field, ReferenceCriterion* c, std::string* error);

// Looks `reference` up in a list of course scenes (tests/course/course_scenes.txt: NAME SCENE
// REFERENCE CRITERION [flags]; REFERENCE relative to the scenes directory): the line whose
// REFERENCE ends the given path. Sets *name and *field (the CRITERION) and returns true;
// false when no line matches. Throws std::runtime_error when the list cannot be read.
bool find_course_criterion(const std::string& list, const std::string& reference, std::string* name,
                           std::string* field);

// The figures and the verdict line "PASS (criterion K)" / "FAIL (criterion K)" that the
// reference tests print, after `label` and `detail` (e.g. the size and the subset used).
void print_reference_result(const std::string& label, const std::string& detail,
                            const ReferenceResult& r, const ReferenceCriterion& c, long pixels);

}  // namespace cmp
