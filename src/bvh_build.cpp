#include "bvh_build.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <numeric>
#include <thread>

#include "cl/bvh.h"

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

// Past this depth splits fall back to the object median, which halves the count, so
// the depth stays below RT_BVH_MAX_DEPTH for up to 2^27 primitives per level.
constexpr int kMedianDepth = RT_BVH_MAX_DEPTH - 28;
// Subtrees of at most this many primitives are built as separate tasks, in parallel; the
// levels above are built in order, their binning split across the threads. The threshold
// does not depend on the thread count, so neither does the tree nor its node order.
constexpr int kTaskPrimitives = 1 << 14;
// Ranges at least this long are binned in parallel chunks.
constexpr int kParallelBinning = 1 << 16;

// Runs fn(0) ... fn(count - 1) on up to `threads` threads (the caller's included).
template <class Fn>
void parallel_for(int count, int threads, Fn fn) {
  threads = std::max(1, std::min(threads, count));
  std::atomic<int> next{0};
  auto work = [&] {
    for (int i; (i = next.fetch_add(1)) < count;) fn(i);
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(work);
  work();
  for (auto& t : pool) t.join();
}

// Per-axis bins; fixed arrays, so the many small nodes near the leaves allocate nothing.
constexpr int kMaxBins = 256;
struct Bins {
  Aabb box[kMaxBins];
  int count[kMaxBins];
  void clear(int nb) {
    for (int j = 0; j < nb; ++j) box[j] = Aabb(), count[j] = 0;
  }
};

class Builder {
 public:
  Builder(const std::vector<Aabb>& boxes, const BvhOptions& options, int max_leaf, int prim_offset,
          std::vector<BinaryBvhNode>& nodes, std::vector<int>& order)
      : boxes_(boxes),
        opt_(options),
        max_leaf_(max_leaf),
        offset_(prim_offset),
        threads_(options.threads > 0 ? options.threads
                                     : static_cast<int>(std::thread::hardware_concurrency())),
        nodes_(nodes),
        order_(order) {
    centroids_.resize(boxes.size() * 3);
    parallel_for(chunks(static_cast<int>(boxes.size())), threads_, [&](int c) {
      int n = static_cast<int>(boxes.size());
      for (int i = chunk_begin(c, n); i < chunk_begin(c + 1, n); ++i)
        for (int k = 0; k < 3; ++k)
          centroids_[i * 3 + k] = 0.5f * (boxes[i].lo[k] + boxes[i].hi[k]);
    });
  }

  BvhBuildResult run() {
    BvhBuildResult r;
    order_.resize(boxes_.size());
    std::iota(order_.begin(), order_.end(), 0);
    r.root = static_cast<int>(nodes_.size());
    nodes_.emplace_back();
    Context top(nodes_, 0, true);
    build(top, r.root, 0, static_cast<int>(boxes_.size()), 0);
    // Each deferred subtree is built into its own array, then spliced in task order.
    local_.resize(tasks_.size());
    std::vector<Context> done;
    for (auto& l : local_) done.emplace_back(l, 0, false);
    parallel_for(static_cast<int>(tasks_.size()), threads_, [&](int t) {
      const Task& k = tasks_[t];
      done[t].nodes->emplace_back();
      build(done[t], 0, k.begin, k.end, k.depth);
    });
    int depth = top.max_depth;
    for (size_t t = 0; t < tasks_.size(); ++t) {
      splice(*done[t].nodes, tasks_[t].node);
      depth = std::max(depth, done[t].max_depth);
    }
    r.depth = depth;
    return r;
  }

 private:
  struct Context {
    Context(std::vector<BinaryBvhNode>& n, int d, bool defer)
        : nodes(&n), max_depth(d), may_defer(defer) {}
    std::vector<BinaryBvhNode>* nodes;
    int max_depth;
    bool may_defer;
  };
  struct Task {
    int node, begin, end, depth;
  };

  // Chunks of a range for parallel loops: fixed by the range alone, never by the threads.
  static int chunks(int n) { return n >= kParallelBinning ? 16 : 1; }
  static int chunk_begin(int c, int n) {
    return static_cast<int>(static_cast<long long>(n) * c / chunks(n));
  }

  float centroid(int prim, int axis) const { return centroids_[prim * 3 + axis]; }

  void make_leaf(BinaryBvhNode& n, int begin, int end) {
    n.first = offset_ + begin;
    n.count = end - begin;
  }

  // Moves a subtree built with local indices (root at 0) into nodes_, its root at `at`.
  void splice(const std::vector<BinaryBvhNode>& local, int at) {
    int base = static_cast<int>(nodes_.size()) - 1;  // Local index i > 0 goes to base + i.
    for (size_t i = 0; i < local.size(); ++i) {
      BinaryBvhNode n = local[i];
      if (n.count <= 0) n.first += base;
      if (i == 0)
        nodes_[at] = n;
      else
        nodes_.push_back(n);
    }
  }

  // The bounds of the primitives' boxes and of their centroids over [begin, end).
  void bounds(int begin, int end, Aabb* box, Aabb* cbox) {
    auto run = [&](int from, int to, Aabb* b, Aabb* c) {
      for (int i = from; i < to; ++i) {
        int p = order_[i];
        b->grow(boxes_[p]);
        c->grow(centroid(p, 0), centroid(p, 1), centroid(p, 2));
      }
    };
    int n = end - begin, nc = chunks(n);
    if (nc == 1) return run(begin, end, box, cbox);
    std::vector<Aabb> b(nc), c(nc);
    parallel_for(nc, threads_, [&](int k) {
      run(begin + chunk_begin(k, n), begin + chunk_begin(k + 1, n), &b[k], &c[k]);
    });
    for (int k = 0; k < nc; ++k) box->grow(b[k]), cbox->grow(c[k]);
  }

  void build(Context& ctx, int node_index, int begin, int end, int depth) {
    ctx.max_depth = std::max(ctx.max_depth, depth);
    int count = end - begin;
    if (ctx.may_defer && count <= kTaskPrimitives) {
      tasks_.push_back(Task{node_index, begin, end, depth});
      return;
    }
    Aabb box, cbox;
    bounds(begin, end, &box, &cbox);
    std::vector<BinaryBvhNode>& nodes = *ctx.nodes;
    BinaryBvhNode& n = nodes[node_index];
    for (int k = 0; k < 3; ++k) {
      n.lo[k] = box.lo[k];
      n.hi[k] = box.hi[k];
    }
    if (count <= max_leaf_ && (count == 1 || max_leaf_ > 1)) {
      make_leaf(n, begin, end);
      return;
    }
    int axis = 0, mid = -1;
    if (depth < kMedianDepth) mid = sah_split(box, cbox, begin, end, &axis);
    if (mid == -2) {  // The SAH prefers a leaf.
      make_leaf(n, begin, end);
      return;
    }
    if (mid < 0) {
      // Object median along the widest centroid extent: always progresses.
      float best = -1;
      for (int k = 0; k < 3; ++k)
        if (cbox.hi[k] - cbox.lo[k] > best) best = cbox.hi[k] - cbox.lo[k], axis = k;
      mid = (begin + end) / 2;
      std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                       [&](int a, int b) { return centroid(a, axis) < centroid(b, axis); });
    }
    int left = static_cast<int>(nodes.size());
    nodes.emplace_back();
    nodes.emplace_back();
    nodes[node_index].first = left;
    nodes[node_index].count = -axis;
    build(ctx, left, begin, mid, depth + 1);
    build(ctx, left + 1, mid, end, depth + 1);
  }

  // Bins the centroids of [from, to) along every axis with a usable extent into axes[].
  void bin_range(const Aabb& cbox, int from, int to, int nb, Bins axes[3]) {
    for (int axis = 0; axis < 3; ++axis) {
      float lo = cbox.lo[axis], extent = cbox.hi[axis] - lo;
      axes[axis].clear(nb);
      if (!(extent > 0)) continue;
      float scale = nb / extent;
      Bins& b = axes[axis];
      for (int i = from; i < to; ++i) {
        int p = order_[i];
        int j = std::min(nb - 1, static_cast<int>((centroid(p, axis) - lo) * scale));
        b.box[j].grow(boxes_[p]);
        ++b.count[j];
      }
    }
  }

  // Bins [begin, end), in parallel chunks when long. Boxes merge by min / max and counts
  // by sums, both exact, so chunking cannot change the result.
  void bin(const Aabb& cbox, int begin, int end, int nb, Bins axes[3]) {
    int n = end - begin, nc = chunks(n);
    if (nc == 1) return bin_range(cbox, begin, end, nb, axes);
    std::vector<Bins> part(nc * 3);
    parallel_for(nc, threads_, [&](int k) {
      bin_range(cbox, begin + chunk_begin(k, n), begin + chunk_begin(k + 1, n), nb, &part[k * 3]);
    });
    for (int axis = 0; axis < 3; ++axis) {
      axes[axis].clear(nb);
      for (int k = 0; k < nc; ++k)
        for (int j = 0; j < nb; ++j) {
          axes[axis].box[j].grow(part[k * 3 + axis].box[j]);
          axes[axis].count[j] += part[k * 3 + axis].count[j];
        }
    }
  }

  // Returns the partition point of the best binned-SAH split (and its axis), -2 when a
  // leaf is cheaper, or -1 when no split separates the centroids.
  int sah_split(const Aabb& box, const Aabb& cbox, int begin, int end, int* axis_out) {
    const int nb = std::min(kMaxBins, std::max(2, opt_.bins));
    float best_cost = 3.4e38f;
    int best_axis = -1, best_bin = -1;
    Bins axes[3];
    bin(cbox, begin, end, nb, axes);
    float right_area[kMaxBins];
    int right_count[kMaxBins];
    for (int axis = 0; axis < 3; ++axis) {
      if (!(cbox.hi[axis] - cbox.lo[axis] > 0)) continue;
      const Bins& bins = axes[axis];
      Aabb acc;
      int cnt = 0;
      for (int b = nb - 1; b > 0; --b) {
        acc.grow(bins.box[b]);
        cnt += bins.count[b];
        right_area[b] = acc.area();
        right_count[b] = cnt;
      }
      acc = Aabb();
      cnt = 0;
      for (int b = 0; b < nb - 1; ++b) {
        acc.grow(bins.box[b]);
        cnt += bins.count[b];
        if (cnt == 0 || right_count[b + 1] == 0) continue;
        float cost = acc.area() * cnt + right_area[b + 1] * right_count[b + 1];
        if (cost < best_cost) best_cost = cost, best_axis = axis, best_bin = b;
      }
    }
    if (best_axis < 0) return -1;
    // Costs relative to intersecting every primitive: traversal step 1, intersection 1.
    float leaf_cost = static_cast<float>(end - begin);
    float split_cost = 1.0f + best_cost / std::max(box.area(), 1e-30f);
    if (end - begin <= max_leaf_ && split_cost >= leaf_cost) return -2;
    float lo = cbox.lo[best_axis], scale = nb / (cbox.hi[best_axis] - lo);
    auto mid = std::partition(order_.begin() + begin, order_.begin() + end, [&](int p) {
      return std::min(nb - 1, static_cast<int>((centroid(p, best_axis) - lo) * scale)) <= best_bin;
    });
    *axis_out = best_axis;
    return static_cast<int>(mid - order_.begin());
  }

  const std::vector<Aabb>& boxes_;
  const BvhOptions& opt_;
  int max_leaf_, offset_, threads_;
  std::vector<BinaryBvhNode>& nodes_;
  std::vector<int>& order_;
  std::vector<float> centroids_;
  std::vector<Task> tasks_;
  std::vector<std::vector<BinaryBvhNode>> local_;
};

}  // namespace

BvhBuildResult build_bvh(const std::vector<Aabb>& boxes, const BvhOptions& options, int max_leaf,
                         int prim_offset, std::vector<BinaryBvhNode>& nodes,
                         std::vector<int>& order) {
  if (boxes.empty()) return {};
  return Builder(boxes, options, max_leaf, prim_offset, nodes, order).run();
}

}  // namespace rt
