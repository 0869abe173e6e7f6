// A render's checkpoint: the raw film (every pixel's PixelAccum and PrimaryInfo, as the
// device holds them) after `spp` samples, with a key of everything that changes pixels.
// The sampler is stateless and every device adds a pixel's samples in order, so a film
// loaded back and continued from sample `spp` ends with the bytes of an uninterrupted
// render (src/device/device.h, RenderDevice::render).
//
// File format (written atomically, io/file_util.h), version 1:
//   "rtcheckpoint 1\n"
//   one "<name> <value>\n" line per key field (CheckpointKey, in order)
//   "spp <k>\n"
//   only when rows hold different counts (a distributed render stopped with its bands at
//   different passes): "rows <r1>x<s1>,<r2>x<s2>,...\n", runs of r rows holding s samples,
//   top to bottom; k is then their least
//   "pixels <n>\n" "\n"
//   n PixelAccum records, then n PrimaryInfo records, raw (this host's byte order; the
//   key's "film" field holds their sizes, so a build with another layout is refused).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "cl/film/film_types.h"

namespace rt {

// Named fields, compared in order; values are single-line text.
using CheckpointKey = std::vector<std::pair<std::string, std::string>>;

struct Checkpoint {
  CheckpointKey key;
  int spp = 0;
  std::vector<int> row_spp;  // Samples each row holds; empty when every row holds spp.
  std::vector<PixelAccum> accum;
  std::vector<PrimaryInfo> primary;
};

// "<image>.rtcheckpoint".
std::string checkpoint_path_for(const std::string& image);

// Throws std::runtime_error("<path>: cannot write checkpoint: <reason>").
void write_checkpoint(const std::string& path, const Checkpoint& c);

// Throws std::runtime_error("<path>: cannot read checkpoint: <reason>").
Checkpoint read_checkpoint(const std::string& path);

// The key and counts alone (no film), for a look at what a checkpoint holds; throws as
// read_checkpoint.
Checkpoint read_checkpoint_header(const std::string& path);

// Empty when `saved` equals `now`; else one phrase naming the first field that differs:
// "seed is 1 in the checkpoint, 2 in this run".
std::string key_difference(const CheckpointKey& saved, const CheckpointKey& now);

// 64-bit FNV-1a of the bytes of every file in `paths`, in hex; throws
// std::runtime_error("<path>: cannot read: <reason>").
std::string files_hash(const std::vector<std::string>& paths);

}  // namespace rt
