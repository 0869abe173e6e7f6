// 8-bit RGB images and their PNG encoding: conversion from the renderer's float buffer, an
// atomic PNG writer, and a reader that accepts any PNG the reference images might use.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace rt {

// 8-bit RGB, row-major, top row first; rgb.size() == width * height * 3.
struct Image8 {
  int width = 0, height = 0;
  std::vector<uint8_t> rgb;
  // A partial render's sample count ("123 of 900", io/partial_mark.h), written as the
  // PNG's tEXt chunk (or the JPEG's comment) kSamplesMarkKey; empty for a finished image,
  // which then carries no chunk and keeps its bytes.
  std::string samples_mark;
};

// How radiance becomes an 8-bit level after clamping to [0, 255]. The course's renderer
// truncates (a cast to unsigned char), so its official images sit up to one level below
// a rounded conversion of the same radiance: truncation reproduces them exactly, rounding
// is the unbiased choice for everything else.
enum class Quantize { kTruncate, kRound };

// Converts linear float RGB (3 floats per pixel, row-major, nominal range [0, 255]) to 8 bits.
// Each value is clamped to [0, 255], then truncated (the course's convention, the default)
// or rounded half away from zero (std::lround); NaN -> 0. No gamma is applied.
// Throws std::invalid_argument if rgb.size() != width * height * 3.
Image8 to_8bit(int width, int height, const std::vector<float>& rgb,
               Quantize quantize = Quantize::kTruncate);

// Writes a PNG atomically (encoded in memory, then write_file_atomic of io/file_util.h). On any
// failure (directory missing or unwritable, libpng error, disk full, inconsistent image) no new
// file appears at <path> (an existing one is left untouched), no temporary file remains, and
// std::runtime_error is thrown with the one-line message "<path>: cannot write PNG: <reason>".
void write_png(const std::string& path, const Image8& image);

// Reads an 8- or 16-bit (or 1/2/4-bit) PNG of any color type and returns 8-bit RGB: gray is
// replicated, palettes expanded, alpha dropped (not composited), 16-bit samples scaled to 8.
// Gamma chunks are ignored, so stored sample values come back unchanged.
// Throws std::runtime_error("<path>: cannot read PNG: <reason>") on any failure, including
// corrupt or truncated files and images over 2^30 bytes of RGB.
Image8 read_png(const std::string& path);

}  // namespace rt
