// Host-side access to single lanes of the wide BVH's nodes (BvhNode) and triangle blocks
// (TriangleBlock) of cl/scene_types.h at a width chosen per device at run time
// (BvhOptions::width): the CPU reference traverses this build's RT_BVH_WIDTH, an OpenCL
// kernel is compiled for whichever width it is handed. A node of width W has the layout
// BvhNode has when compiled with RT_BVH_WIDTH = W: six bound vectors, the child vector and a
// padding vector of W lanes each (32 W bytes); a block nine coordinate vectors and `first`,
// padded to 40 W bytes. FlatScene keeps both arrays as vectors of this build's types, so
// W / RT_BVH_WIDTH elements make one node or block of width W (wide_units).
#pragma once

#include <cstddef>
#include <cstring>

#include "cl/scene_types.h"
#include "util/page_aligned.h"

namespace rt {

// Bytes per lane: a node holds eight vectors of 4-byte lanes (six bounds, the children,
// padding), a block ten (nine coordinates, then `first` and padding).
constexpr size_t kNodeBytesPerLane = 32;
constexpr size_t kBlockBytesPerLane = 40;
constexpr int kNodeChildVector = 6;   // After the six bounds.
constexpr int kBlockFirstVector = 9;  // After the nine coordinates.

static_assert(sizeof(BvhNode) == kNodeBytesPerLane * RT_BVH_WIDTH &&
                  offsetof(BvhNode, child) == 4 * kNodeChildVector * RT_BVH_WIDTH,
              "BvhNode layout");
static_assert(sizeof(TriangleBlock) == kBlockBytesPerLane * RT_BVH_WIDTH &&
                  offsetof(TriangleBlock, first) == 4 * kBlockFirstVector * RT_BVH_WIDTH,
              "TriangleBlock layout");

// The widest node the host builds (BvhOptions::width: 4 or 8).
constexpr int kMaxBvhWidth = 8;

// Array elements per node or block of `width` lanes (a multiple of RT_BVH_WIDTH).
inline size_t wide_units(int width) { return static_cast<size_t>(width / RT_BVH_WIDTH); }

// Whether nodes of `width` lanes can be built by this host: 4 or 8, a multiple of its own.
inline bool valid_bvh_width(int width) {
  return (width == 4 || width == kMaxBvhWidth) && width % RT_BVH_WIDTH == 0;
}

// The nodes of one width in a FlatScene's node array.
class WideNodes {
 public:
  WideNodes(PageAlignedVector<BvhNode>& v, int width) : v_(v), width_(width) {}

  int width() const { return width_; }
  size_t size() const { return v_.size() / wide_units(width_); }
  // Appends a node of zero bytes and returns its index.
  size_t append() {
    size_t index = size();
    v_.resize(v_.size() + wide_units(width_));
    std::memset(static_cast<void*>(&v_[index * wide_units(width_)]), 0, node_bytes());
    return index;
  }
  void reserve(size_t nodes) { v_.reserve(nodes * wide_units(width_)); }
  size_t capacity() const { return v_.capacity() / wide_units(width_); }

  // Vector `vec` of the node: bounds 0-5 (lo x, y, z, hi x, y, z), then the children.
  void set_bound(size_t node, int vec, int lane, float value) {
    std::memcpy(bytes() + offset(node, vec, lane), &value, sizeof value);
  }
  void set_child(size_t node, int lane, int ref) {
    std::memcpy(bytes() + offset(node, kNodeChildVector, lane), &ref, sizeof ref);
  }
  int child(size_t node, int lane) const {
    int ref;
    std::memcpy(&ref, bytes() + offset(node, kNodeChildVector, lane), sizeof ref);
    return ref;
  }
  float bound(size_t node, int vec, int lane) const {
    float value;
    std::memcpy(&value, bytes() + offset(node, vec, lane), sizeof value);
    return value;
  }

 private:
  size_t node_bytes() const { return kNodeBytesPerLane * width_; }
  size_t offset(size_t node, int vec, int lane) const {
    return node * node_bytes() + 4 * (static_cast<size_t>(vec) * width_ + lane);
  }
  char* bytes() { return reinterpret_cast<char*>(v_.data()); }
  const char* bytes() const { return reinterpret_cast<const char*>(v_.data()); }

  PageAlignedVector<BvhNode>& v_;
  int width_;
};

// One triangle block of `width` lanes, built on the host and appended whole.
class WideBlock {
 public:
  explicit WideBlock(int width) : width_(width) { std::memset(bytes_, 0, sizeof bytes_); }
  // Coordinate `j` (3 k + axis of vertex k) of lane `lane`.
  void set(int j, int lane, float value) {
    std::memcpy(bytes_ + 4 * (j * width_ + lane), &value, 4);
  }
  void set_first(int first) { std::memcpy(bytes_ + 4 * kBlockFirstVector * width_, &first, 4); }
  void append_to(PageAlignedVector<TriangleBlock>& blocks) const {
    size_t at = blocks.size();
    blocks.resize(at + wide_units(width_));
    std::memcpy(static_cast<void*>(&blocks[at]), bytes_, kBlockBytesPerLane * width_);
  }

 private:
  int width_;
  char bytes_[kBlockBytesPerLane * kMaxBvhWidth];
};

}  // namespace rt
