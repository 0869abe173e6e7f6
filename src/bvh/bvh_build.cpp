#include "bvh_build.h"

#include "bvh_boxes4.h"

#include <algorithm>
#include <cstring>
#include <memory>
#include <new>

#include "cl/bvh/bvh.h"
#include "util/job_stack.h"
#include "util/parallel_for.h"

namespace rt {

void Aabb::grow(const Aabb& b) {
  for (int k = 0; k < 3; ++k) {
    lo[k] = std::min(lo[k], b.lo[k]);
    hi[k] = std::max(hi[k], b.hi[k]);
  }
}

void Aabb::grow(float x, float y, float z) {
  float p[3] = {x, y, z};
  for (int k = 0; k < 3; ++k) {
    lo[k] = std::min(lo[k], p[k]);
    hi[k] = std::max(hi[k], p[k]);
  }
}

float Aabb::area() const {
  if (empty()) return 0;
  float dx = hi[0] - lo[0], dy = hi[1] - lo[1], dz = hi[2] - lo[2];
  return 2.0f * (dx * dy + dy * dz + dz * dx);
}

namespace {

using namespace bvh_detail;

// Past this depth splits fall back to the object median, which halves the count, so
// the depth stays below RT_BVH_MAX_DEPTH for up to 2^27 primitives per level.
constexpr int kMedianDepth = RT_BVH_MAX_DEPTH - 28;
// Nodes of more primitives are split as jobs of their own, which any thread may take;
// a node of at most this many is built whole, with its subtree, by one thread. Neither
// the threshold nor anything else depends on the thread count, so neither does the tree.
constexpr int kTaskPrimitives = 1 << 14;
// Primitives per piece of the passes over all of them.
constexpr size_t kGrain = 1 << 16;

struct Split {
  int mid = -1, axis = 0;
  Box4 box[2], cbox[2];  // Of the primitives' boxes and of their centroids, per side.
};

// A node of the levels split as separate jobs, or a subtree built whole (`local_size`
// nodes at `local`, root first, children indices local).
struct Record {
  BinaryBvhNode node{};
  Record* child[2] = {nullptr, nullptr};
  BinaryBvhNode* local = nullptr;
  int local_size = 0;
  int max_depth = 0;
};

struct Job {
  Record* record;
  int begin, end, depth;
  Box4 box, cbox;
};

class Builder {
 public:
  Builder(std::vector<BvhPrimitive>& prims, const BvhOptions& options, int max_leaf,
          int prim_offset, std::vector<BinaryBvhNode>& nodes)
      : prims_(prims.data()),
        count_(static_cast<int>(prims.size())),
        bins_(std::min(kMaxBins, std::max(2, options.bins))),
        max_leaf_(max_leaf),
        offset_(prim_offset),
        threads_(resolve_threads(options.threads)),
        nodes_(nodes),
        // A subtree of n primitives has at most 2n - 1 nodes, so the subtree over positions
        // [begin, end) is given the slots [2 begin, 2 end) of one array. Most of it is
        // never written and, left unset (operator new, not a vector), never touches memory;
        // one block for all, not one per subtree, so the allocator hands it all back at the
        // end (many medium blocks freed at once stay in its heap, raising peak memory).
        pool_(static_cast<BinaryBvhNode*>(::operator new(2 * sizeof(BinaryBvhNode) * count_))) {}

  BvhBuildResult run() {
    // The bounds of everything, in pieces merged in their order.
    const size_t pieces = piece_count(count_, kGrain);
    std::vector<Box4> box(pieces), cbox(pieces);
    parallel_ranges(count_, kGrain, threads_, [&](size_t k, size_t from, size_t to) {
      bounds(static_cast<int>(from), static_cast<int>(to), &box[k], &cbox[k]);
    });
    Job root{jobs_.new_record(), 0, count_, 0, Box4(), Box4()};
    for (size_t k = 0; k < pieces; ++k) root.box.grow(box[k]), root.cbox.grow(cbox[k]);
    jobs_.push(root);
    jobs_.run(threads_, [&](const Job& j) { process(j); });
    BvhBuildResult r;
    r.root = static_cast<int>(nodes_.size());
    nodes_.reserve(nodes_.size() + 1 + count_nodes(root.record));
    nodes_.emplace_back();
    place(root.record, r.root, &r.depth);
    return r;
  }

 private:
  void process(const Job& j) {
    Record& rec = *j.record;
    if (j.end - j.begin <= kTaskPrimitives) {
      rec.local = pool_.get() + 2 * static_cast<size_t>(j.begin);
      rec.local_size = 1;
      build(rec, 0, j.begin, j.end, j.depth, j.box, j.cbox);
      return;
    }
    rec.max_depth = j.depth;
    store_box(rec.node, j.box);
    Split s;
    if (!split(j.begin, j.end, j.depth, j.box, j.cbox, &s))
      return make_leaf(rec.node, j.begin, j.end);
    rec.node.count = -s.axis;
    for (int side = 1; side >= 0; --side) {  // The left side is taken first.
      rec.child[side] = jobs_.new_record();
      int from = side ? s.mid : j.begin, to = side ? j.end : s.mid;
      jobs_.push(Job{rec.child[side], from, to, j.depth + 1, s.box[side], s.cbox[side]});
    }
  }

  // Nodes below the root of `rec`.
  static size_t count_nodes(const Record* rec) {
    if (rec->local) return rec->local_size - 1;
    if (rec->node.count > 0) return 0;
    return 2 + count_nodes(rec->child[0]) + count_nodes(rec->child[1]);
  }

  // Copies the tree of `rec` into nodes_, its root at `at`, in depth-first order.
  void place(const Record* rec, int at, int* depth) {
    *depth = std::max(*depth, rec->max_depth);
    if (rec->local) {
      int base = static_cast<int>(nodes_.size()) - 1;  // Local index i > 0 goes to base + i.
      for (int i = 0; i < rec->local_size; ++i) {
        BinaryBvhNode n = rec->local[i];
        if (n.count <= 0) n.first += base;
        if (i == 0)
          nodes_[at] = n;
        else
          nodes_.push_back(n);
      }
      return;
    }
    BinaryBvhNode n = rec->node;
    if (n.count > 0) {
      nodes_[at] = n;
      return;
    }
    n.first = static_cast<int>(nodes_.size());
    nodes_[at] = n;
    nodes_.emplace_back();
    nodes_.emplace_back();
    place(rec->child[0], n.first, depth);
    place(rec->child[1], n.first + 1, depth);
  }

  static void store_box(BinaryBvhNode& n, const Box4& b) {
    for (int k = 0; k < 3; ++k) {
      n.lo[k] = b.lo[k];
      n.hi[k] = b.hi[k];
    }
  }

  void make_leaf(BinaryBvhNode& n, int begin, int end) {
    n.first = offset_ + begin;
    n.count = end - begin;
  }

  void bounds(int begin, int end, Box4* box, Box4* cbox) const {
    for (int i = begin; i < end; ++i) {
      const Prim p = load(prims_[i]);
      box->grow(p.lo, p.hi);
      Vec4 c = centroid(p);
      cbox->grow(c, c);
    }
  }

  // Builds the subtree of [begin, end) below rec.local[node_index], whose box is `box`.
  void build(Record& rec, int node_index, int begin, int end, int depth, const Box4& box,
             const Box4& cbox) {
    rec.max_depth = std::max(rec.max_depth, depth);
    BinaryBvhNode& n = rec.local[node_index];
    store_box(n, box);
    Split s;
    if (!split(begin, end, depth, box, cbox, &s)) return make_leaf(n, begin, end);
    const int left = rec.local_size;
    n.first = left;
    n.count = -s.axis;
    rec.local_size += 2;
    build(rec, left, begin, s.mid, depth + 1, s.box[0], s.cbox[0]);
    build(rec, left + 1, s.mid, end, depth + 1, s.box[1], s.cbox[1]);
  }

  // Chooses how [begin, end) splits and partitions it; false when it stays a leaf.
  bool split(int begin, int end, int depth, const Box4& box, const Box4& cbox, Split* s) {
    const int count = end - begin;
    if (count <= max_leaf_ && (count == 1 || max_leaf_ > 1)) return false;
    int mid = -1;
    if (depth < kMedianDepth) mid = sah_split(begin, end, box, cbox, s);
    if (mid == -2) return false;  // The SAH prefers a leaf.
    if (mid < 0) median_split(begin, end, cbox, s);
    return true;
  }

  // Object median along the widest centroid extent: always progresses.
  void median_split(int begin, int end, const Box4& cbox, Split* s) {
    float best = -1;
    for (int k = 0; k < 3; ++k)
      if (cbox.hi[k] - cbox.lo[k] > best) best = cbox.hi[k] - cbox.lo[k], s->axis = k;
    const int axis = s->axis;
    s->mid = (begin + end) / 2;
    std::nth_element(prims_ + begin, prims_ + s->mid, prims_ + end,
                     [axis](const BvhPrimitive& a, const BvhPrimitive& b) {
                       return 0.5f * (a.lo[axis] + a.hi[axis]) < 0.5f * (b.lo[axis] + b.hi[axis]);
                     });
    bounds(begin, s->mid, &s->box[0], &s->cbox[0]);
    bounds(s->mid, end, &s->box[1], &s->cbox[1]);
  }

  // Returns the partition point of the best binned-SAH split (its axis and both sides'
  // bounds in *s), -2 when a leaf is cheaper, or -1 when no split separates the centroids.
  int sah_split(int begin, int end, const Box4& box, const Box4& cbox, Split* s) {
    const int nb = bins_;
    const Binning binning(cbox, nb);
    Bins bins;
    for (int axis = 0; axis < 3; ++axis)
      for (int j = 0; j < nb; ++j) new (&bins.box[axis][j]) Box4(), bins.count[axis][j] = 0;
    // Every axis in one pass; an axis without extent bins everything into bin 0.
    for (int i = begin; i < end; ++i) {
      const Prim p = load(prims_[i]);
      Vec4i j = binning.bin(centroid(p));
      for (int axis = 0; axis < 3; ++axis) {
        bins.box[axis][j[axis]].grow(p.lo, p.hi);
        ++bins.count[axis][j[axis]];
      }
    }
    float best_cost = 3.4e38f;
    int best_axis = -1, best_bin = -1;
    float right_area[kMaxBins];
    int right_count[kMaxBins];
    for (int axis = 0; axis < 3; ++axis) {
      if (!(cbox.hi[axis] - cbox.lo[axis] > 0)) continue;
      // An empty bin leaves the sums as they were, so their area is not computed again.
      Box4 acc;
      int cnt = 0;
      float area = 0;
      for (int b = nb - 1; b > 0; --b) {
        if (bins.count[axis][b]) {
          acc.grow(bins.box[axis][b]);
          cnt += bins.count[axis][b];
          area = acc.area();
        }
        right_area[b] = area;
        right_count[b] = cnt;
      }
      acc = Box4();
      cnt = 0;
      area = 0;
      for (int b = 0; b < nb - 1; ++b) {
        if (bins.count[axis][b]) {
          acc.grow(bins.box[axis][b]);
          cnt += bins.count[axis][b];
          area = acc.area();
        }
        if (cnt == 0 || right_count[b + 1] == 0) continue;
        float cost = area * cnt + right_area[b + 1] * right_count[b + 1];
        if (cost < best_cost) best_cost = cost, best_axis = axis, best_bin = b;
      }
    }
    if (best_axis < 0) return -1;
    // Costs relative to intersecting every primitive: traversal step 1, intersection 1.
    float leaf_cost = static_cast<float>(end - begin);
    float split_cost = 1.0f + best_cost / std::max(box.area(), 1e-30f);
    if (end - begin <= max_leaf_ && split_cost >= leaf_cost) return -2;
    s->axis = best_axis;
    s->mid = partition(begin, end, binning, best_axis, best_bin, s);
    return s->mid;
  }

  // Moves the primitives of [begin, end) whose bin along `axis` is at most `last_bin` to
  // the front and returns where the rest start, growing each side's bounds on the way.
  // The swaps are those of libstdc++'s std::partition (bidirectional form), so the order
  // within each side, and with it the tree, is the one earlier versions built.
  int partition(int begin, int end, const Binning& binning, int axis, int last_bin, Split* s) {
    BvhPrimitive* first = prims_ + begin;
    BvhPrimitive* last = prims_ + end;
    Box4 box[2], cbox[2];
    auto side = [&](const BvhPrimitive& q) {  // 0: left, 1: right; grows that side's bounds.
      const Prim p = load(q);
      Vec4 c = centroid(p);
      int k = binning.bin(c)[axis] <= last_bin ? 0 : 1;
      box[k].grow(p.lo, p.hi);
      cbox[k].grow(c, c);
      return k;
    };
    for (;;) {
      while (first != last && side(*first) == 0) ++first;
      if (first == last) break;
      --last;  // *first belongs to the right.
      while (first != last && side(*last) == 1) --last;
      if (first == last) break;
      std::swap(*first, *last);
      ++first;
    }
    for (int k = 0; k < 2; ++k) s->box[k] = box[k], s->cbox[k] = cbox[k];
    return static_cast<int>(first - prims_);
  }

  BvhPrimitive* prims_;
  int count_, bins_, max_leaf_, offset_, threads_;
  std::vector<BinaryBvhNode>& nodes_;
  struct FreeRaw {
    void operator()(BinaryBvhNode* p) const { ::operator delete(p); }
  };
  std::unique_ptr<BinaryBvhNode, FreeRaw> pool_;
  JobStack<Job, Record> jobs_;
};

}  // namespace

BvhBuildResult build_bvh(std::vector<BvhPrimitive>& prims, const BvhOptions& options, int max_leaf,
                         int prim_offset, std::vector<BinaryBvhNode>& nodes) {
  if (prims.empty()) return {};
  return Builder(prims, options, max_leaf, prim_offset, nodes).run();
}

BvhBuildResult build_bvh(const std::vector<Aabb>& boxes, const BvhOptions& options, int max_leaf,
                         int prim_offset, std::vector<BinaryBvhNode>& nodes,
                         std::vector<int>& order) {
  std::vector<BvhPrimitive> prims(boxes.size());
  for (size_t i = 0; i < boxes.size(); ++i) {
    BvhPrimitive& p = prims[i];
    for (int k = 0; k < 3; ++k) p.lo[k] = boxes[i].lo[k], p.hi[k] = boxes[i].hi[k];
    p.index = static_cast<int>(i);
    p.unused = 0;
  }
  BvhBuildResult r = build_bvh(prims, options, max_leaf, prim_offset, nodes);
  order.resize(prims.size());
  for (size_t i = 0; i < prims.size(); ++i) order[i] = prims[i].index;
  return r;
}

}  // namespace rt
