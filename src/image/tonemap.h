// The photographic tone-mapping operator of Reinhard et al. 2002 (global version), with
// the conventions of the course's assignment 5 (hw5/SPEC.txt) as recovered from its own
// EXR/PNG pairs: it turns the HDR film into the 8-bit image written beside the .exr.
#pragma once

#include "image/image.h"
#include "io/png_io.h"

namespace rt {

struct PhotographicParams {
  double key = 0.18;          // The "key value" a: the log-average luminance maps to it.
  double burn_percent = 0.0;  // Share of the brightest pixels allowed to burn out; 0: none.
  double saturation = 1.0;    // Exponent s on the colour ratio C / Y.
  double gamma = 2.2;         // Display gamma of the 8-bit encoding.
};

// Luminance of linear sRGB (Rec. 709 weights, as the specification gives them).
inline double Luminance(double r, double g, double b) {
  return 0.2126 * r + 0.7152 * g + 0.0722 * b;
}

// Tone maps a 3- or 4-channel linear image (alpha is ignored) to 8-bit RGB:
//  1. Y = luminance; the log-average Yavg = exp(mean(log(1e-6 + Y))) over every pixel,
//     background included;
//  2. L = key * Y / Yavg;
//  3. with burn-out, Lwhite = the sorted L at index floor(N (100 - burn) / 100) (clamped to
//     the last pixel) and Ld = L (1 + L / Lwhite^2) / (1 + L); without, Ld = L / (1 + L);
//  4. each colour channel C -> Ld (C / Y)^saturation (0 where Y <= 0), clamped to [0, 1];
//  5. 255 x^(1 / gamma), truncated to an integer (the course's images truncate, although
//     the specification says round).
// Throws std::invalid_argument on an image with other than 3 or 4 channels.
Image8 TonemapPhotographic(const ImageF& hdr, const PhotographicParams& params);

// The log-average luminance Yavg of step 1 (0 for an empty image).
double LogAverageLuminance(const ImageF& hdr);

// The operator's two image-wide quantities (steps 1-3), so that pixels can be mapped one at
// a time, e.g. a subset of pixels with the statistics of a whole reference image.
struct PhotographicScale {
  double scale = 1.0;   // key / log-average luminance.
  double white2 = 0.0;  // Lwhite^2; 0: no burn-out.
};
PhotographicScale PhotographicStatistics(const ImageF& hdr, const PhotographicParams& params);

// Steps 2-5 for one linear RGB pixel.
void TonemapPixel(const float rgb[3], const PhotographicScale& s, const PhotographicParams& params,
                  uint8_t out[3]);

}  // namespace rt
