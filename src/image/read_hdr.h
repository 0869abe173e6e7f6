// Readers of high-dynamic-range images: OpenEXR (through the OpenEXR library) and
// Radiance RGBE (.hdr, .pic; a small reader here, since Debian packages no library for it
// beyond header-only code). Both return linear radiance in an rt::ImageF with
// max_value = 0.
#pragma once

#include <string>

#include "image/image.h"

namespace rt {

// Reads an OpenEXR file's R, G, B channels (A too when present, as a 4th channel), or its
// Y channel alone as one grey channel, converted to 32-bit floats whatever their stored
// type. Throws rt::InputError "<path>: cannot read EXR: <reason>".
ImageF read_exr(const std::string& path);

// Reads a Radiance RGBE file: flat or run-length-encoded scanlines, the standard
// "-Y h +X w" orientation (others are rejected). Throws rt::InputError
// "<path>: cannot read HDR: <reason>".
ImageF read_radiance_hdr(const std::string& path);

// Chooses the reader by extension (.exr; .hdr or .pic), case-insensitively.
ImageF read_hdr_image(const std::string& path);

// Whether read_hdr_image reads `path`: its extension is .exr, .hdr or .pic (any case).
bool has_hdr_extension(const std::string& path);

// Reads an HDR file (by extension) as radiance, any other through read_ldr on its
// 0..255 scale: the images textures and environment maps come in.
ImageF read_any_image(const std::string& path);

// Empty when every value is finite and >= 0 (radiance and reflectance read from an HDR
// file must be), else what the first other value is: "texel (3, 0) is -1".
std::string first_invalid_texel(const ImageF& img);

}  // namespace rt
