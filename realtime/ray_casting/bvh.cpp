#include "realtime/ray_casting/bvh.h"

#include "common/input_error.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace gib::rt {

namespace {

constexpr float kFloatMax = std::numeric_limits<float>::max();

struct Box {
  glm::vec3 lo{kFloatMax}, hi{-kFloatMax};

  void grow(const Box& other) {
    lo = glm::min(lo, other.lo);
    hi = glm::max(hi, other.hi);
  }
  // Half the surface area, in double: the SAH weighs by ratios of areas, so the factor 2 cancels.
  double halfArea() const {
    if (hi.x < lo.x) return 0.0;
    const glm::dvec3 e = glm::dvec3(hi) - glm::dvec3(lo);
    return e.x * e.y + e.y * e.z + e.z * e.x;
  }
  glm::vec3 centre() const { return 0.5f * (lo + hi); }
};

// The margin around every triangle's box, as a fraction of the largest coordinate of the set (its
// coordinates are relative to IvmTriangleSet::origin). The IVM test's float arithmetic accepts
// points a few ulps of that magnitude outside the exact region it describes (b = IVM·p rounds
// with an error ~ γ·|p| in space, whatever the IVM's conditioning; p's distance off the plane,
// from t's rounding, likewise), and a ray that runs exactly along a box face with a zero
// direction component is inside or outside the slab as the sign of its zero says
// (kBvhTinyDirection). With this margin no triangle's accepted region, rounding included, comes
// near a box face, so neither decides a hit. 10⁻⁵ is ~170 ulps: the tests' rays along box faces
// found hits outside a box padded by one ulp, none with this margin. It also covers the test's
// rounding term (kIvmRoundingTolerance: a hit at most 4·10⁻⁶ of the ray origin's distance outside
// its triangle) for origins within twice the set's largest coordinate of the triangle.
constexpr double kBoxMargin = 1e-5;

// The bounds of what the IVM test accepts of triangle t, grown by `margin`, in float, rounded
// outward. The test takes a point whose barycentric coordinates are all ≥ −kIvmEdgeTolerance
// (ray_casting_shared.h): the triangle scaled about its centroid g by 1 + 3·tolerance, whose
// vertices are a + 3·tolerance·(a − g). Bounding that, not the triangle, means a hit the brute
// force finds is never outside its leaf's box. Each bound is rounded to float and then moved one
// float outward (std::nextafter), so the float box contains the double one whatever the rounding.
Box acceptedRegionBox(const IvmTriangle& t, double margin) {
  const glm::dvec3 a(t.a), b(t.b), c(t.c);
  const glm::dvec3 g = (a + b + c) / 3.0;
  const double grow = 3.0 * double(gpu::kIvmEdgeTolerance);
  glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
  for (const glm::dvec3& v : {a, b, c}) {
    const glm::dvec3 p = v + grow * (v - g);
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  Box box;
  for (int axis = 0; axis < 3; ++axis) {
    box.lo[axis] = std::nextafter(float(lo[axis] - margin), -kFloatMax);
    box.hi[axis] = std::nextafter(float(hi[axis] + margin), kFloatMax);
  }
  return box;
}

// Inner nodes below a node of n triangles when every split halves it: what a median split needs,
// hence what the depth bound must leave room for.
int medianLevels(std::size_t n, int max_leaf_size) {
  const std::size_t leaves = (n + std::size_t(max_leaf_size) - 1) / std::size_t(max_leaf_size);
  int levels = 0;
  while ((std::size_t{1} << levels) < leaves) ++levels;
  return levels;
}

struct SplitChoice {
  bool found = false;
  int axis = 0;
  int plane = 0;                                     // bins [0, plane) go left
  double cost = std::numeric_limits<double>::max();  // Σ area·count of the two sides
};

class Builder {
 public:
  Builder(const IvmTriangleSet& set, const BvhSettings& settings, Bvh& bvh)
      : settings_(settings), bvh_(bvh) {
    boxes_.reserve(set.size());
    centres_.reserve(set.size());
    const glm::dvec3 largest =
        glm::max(glm::abs(glm::dvec3(set.bounds_min)), glm::abs(glm::dvec3(set.bounds_max)));
    const double margin = kBoxMargin * std::max({largest.x, largest.y, largest.z});
    for (const IvmTriangle& t : set.triangles) {
      boxes_.push_back(acceptedRegionBox(t, margin));
      centres_.push_back(boxes_.back().centre());
    }
    order_.resize(set.size());
    for (std::size_t i = 0; i < order_.size(); ++i) order_[i] = std::uint32_t(i);
  }

  void build() {
    const std::size_t n = order_.size();
    const Box bounds = boundsOf(0, n);
    root_area_ = std::max(bounds.halfArea(), std::numeric_limits<double>::min());
    if (splitWanted(0, n, bounds, 0)) {
      buildInner(0, n, 0);
    } else {
      // One leaf holds the scene: the root is still an inner node, its second child empty
      // under an inverted box (bvhBoxSpan never enters it).
      const std::uint32_t root = allocateNode();
      writeChild(root, 0, bounds, leafReference(0, n, bounds));
      writeChild(root, 1, Box{}, gpu::kBvhEmptyReference);
      ++bvh_.inner_nodes;
      bvh_.max_depth = 1;
      bvh_.sah_cost += settings_.traversal_cost;
    }
    bvh_.triangle_order = std::move(order_);
  }

 private:
  Box boundsOf(std::size_t begin, std::size_t end) const {
    Box box;
    for (std::size_t i = begin; i < end; ++i) box.grow(boxes_[order_[i]]);
    return box;
  }

  Box centreBoundsOf(std::size_t begin, std::size_t end) const {
    Box box;
    for (std::size_t i = begin; i < end; ++i) {
      const glm::vec3 c = centres_[order_[i]];
      box.lo = glm::min(box.lo, c);
      box.hi = glm::max(box.hi, c);
    }
    return box;
  }

  // The bin of a centre along an axis: the same float arithmetic for counting and partitioning.
  // Double precision, so that a centre spread of a few denormals still gives a finite scale.
  int binOf(float centre, float lo, double scale) const {
    const int bin = int((double(centre) - double(lo)) * scale);
    return std::clamp(bin, 0, settings_.bins - 1);
  }

  // Wald's binned SAH over all three axes: counts and boxes per bin, then every plane between
  // bins, scanned from both ends. Ties keep the first axis and plane.
  SplitChoice bestBinnedSplit(std::size_t begin, std::size_t end) const {
    const Box centres = centreBoundsOf(begin, end);
    const int bins = settings_.bins;
    SplitChoice best;
    const auto bin_count = static_cast<std::size_t>(bins);
    std::vector<Box> bin_boxes(bin_count), right_boxes(bin_count);
    std::vector<std::size_t> counts(bin_count);
    for (int axis = 0; axis < 3; ++axis) {
      const float extent = centres.hi[axis] - centres.lo[axis];
      if (!(extent > 0.0f)) continue;  // every centre on one plane: no split along this axis
      const double scale = double(bins) / double(extent);
      std::fill(bin_boxes.begin(), bin_boxes.end(), Box{});
      std::fill(counts.begin(), counts.end(), 0);
      for (std::size_t i = begin; i < end; ++i) {
        const std::uint32_t t = order_[i];
        const int bin = binOf(centres_[t][axis], centres.lo[axis], scale);
        bin_boxes[std::size_t(bin)].grow(boxes_[t]);
        ++counts[std::size_t(bin)];
      }
      // Right side of each plane: bins [plane, bins).
      Box right;
      for (int b = bins - 1; b > 0; --b) {
        right.grow(bin_boxes[std::size_t(b)]);
        right_boxes[std::size_t(b)] = right;
      }
      Box left;
      std::size_t left_count = 0;
      const std::size_t total = end - begin;
      for (int plane = 1; plane < bins; ++plane) {
        left.grow(bin_boxes[std::size_t(plane - 1)]);
        left_count += counts[std::size_t(plane - 1)];
        const std::size_t right_count = total - left_count;
        if (left_count == 0 || right_count == 0) continue;
        const double cost = left.halfArea() * double(left_count) +
                            right_boxes[std::size_t(plane)].halfArea() * double(right_count);
        if (cost < best.cost) best = {true, axis, plane, cost};
      }
    }
    return best;
  }

  // Whether a node of order_[begin, end) with these bounds, `depth` inner nodes above it, is
  // split; when it is, order_[begin, end) is partitioned and split_ holds the middle.
  bool splitWanted(std::size_t begin, std::size_t end, const Box& bounds, int depth) {
    const std::size_t n = end - begin;
    if (n == 1) return false;
    const bool may_be_leaf = n <= std::size_t(settings_.max_leaf_size);
    // As an inner node it would be at depth + 1; its children need room below that.
    if (may_be_leaf && depth + 1 > settings_.max_depth) return false;

    const SplitChoice sah = bestBinnedSplit(begin, end);
    const double area = std::max(bounds.halfArea(), std::numeric_limits<double>::min());
    const double split_cost = settings_.traversal_cost + settings_.triangle_cost * sah.cost / area;
    const double leaf_cost = settings_.triangle_cost * double(n);
    if (may_be_leaf && (!sah.found || leaf_cost <= split_cost)) return false;

    if (sah.found) {
      const std::size_t middle = partitionByBin(begin, end, sah);
      const std::size_t larger = std::max(middle - begin, end - middle);
      if (depth + 1 + medianLevels(larger, settings_.max_leaf_size) <= settings_.max_depth) {
        split_ = middle;
        return true;
      }
    }
    // No SAH split (every centre in one point) or one that would leave the stack too shallow.
    split_ = splitAtMedian(begin, end);
    return true;
  }

  std::size_t partitionByBin(std::size_t begin, std::size_t end, const SplitChoice& split) {
    const Box centres = centreBoundsOf(begin, end);
    const float lo = centres.lo[split.axis];
    const double scale =
        double(settings_.bins) / double(centres.hi[split.axis] - centres.lo[split.axis]);
    const auto middle = std::stable_partition(
        order_.begin() + std::ptrdiff_t(begin), order_.begin() + std::ptrdiff_t(end),
        [&](std::uint32_t t) { return binOf(centres_[t][split.axis], lo, scale) < split.plane; });
    return std::size_t(middle - order_.begin());
  }

  // Half the triangles on each side, by their centres along the axis of the widest centre
  // spread (ties by index, so the order is the same on every run).
  std::size_t splitAtMedian(std::size_t begin, std::size_t end) {
    const Box centres = centreBoundsOf(begin, end);
    const glm::vec3 extent = centres.hi - centres.lo;
    const int axis =
        extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    std::stable_sort(order_.begin() + std::ptrdiff_t(begin), order_.begin() + std::ptrdiff_t(end),
                     [&](std::uint32_t a, std::uint32_t b) {
                       const float ca = centres_[a][axis], cb = centres_[b][axis];
                       return ca < cb || (ca == cb && a < b);
                     });
    return begin + (end - begin) / 2;
  }

  std::uint32_t allocateNode() {
    const std::size_t index = bvh_.nodeCount();
    bvh_.nodes.resize(bvh_.nodes.size() + gpu::kBvhNodeTexels, glm::vec4(0.0f));
    return std::uint32_t(index);
  }

  void writeChild(std::uint32_t node, int child, const Box& box, std::uint32_t reference) {
    glm::vec4* texels = &bvh_.nodes[std::size_t(node) * gpu::kBvhNodeTexels + 2 * child];
    texels[0] = glm::vec4(box.lo, std::bit_cast<float>(reference));
    texels[1] = glm::vec4(box.hi, 0.0f);
  }

  std::uint32_t leafReference(std::size_t begin, std::size_t end, const Box& bounds) {
    const std::size_t n = end - begin;
    ++bvh_.leaves;
    bvh_.max_leaf_size = std::max(bvh_.max_leaf_size, int(n));
    bvh_.sah_cost += settings_.triangle_cost * double(n) * bounds.halfArea() / root_area_;
    return gpu::bvhLeafReference(std::uint32_t(begin), std::uint32_t(n));
  }

  // The inner node over order_[begin, end), already partitioned at split_, `depth` inner nodes
  // above it. Preorder: a node's first child follows it in the array.
  std::uint32_t buildInner(std::size_t begin, std::size_t end, int depth) {
    const std::size_t middle = split_;
    const std::uint32_t node = allocateNode();
    ++bvh_.inner_nodes;
    bvh_.max_depth = std::max(bvh_.max_depth, depth + 1);
    const std::array<std::size_t, 3> cuts = {begin, middle, end};
    Box node_box;
    for (int child = 0; child < 2; ++child) {
      const std::size_t b = cuts[std::size_t(child)], e = cuts[std::size_t(child) + 1];
      const Box box = boundsOf(b, e);
      node_box.grow(box);
      const std::uint32_t reference = splitWanted(b, e, box, depth + 1)
                                          ? buildInner(b, e, depth + 1)
                                          : leafReference(b, e, box);
      writeChild(node, child, box, reference);
    }
    bvh_.sah_cost += settings_.traversal_cost * node_box.halfArea() / root_area_;
    return node;
  }

  const BvhSettings& settings_;
  Bvh& bvh_;
  std::vector<Box> boxes_;          // per set triangle
  std::vector<glm::vec3> centres_;  // per set triangle: its box's centre
  std::vector<std::uint32_t> order_;
  std::size_t split_ = 0;  // the middle splitWanted chose
  double root_area_ = 1.0;
};

void checkSettings(const BvhSettings& s, std::size_t triangles) {
  if (s.max_leaf_size < 1 || s.max_leaf_size > gpu::kBvhMaxLeafSize)
    throw InputError(fmt::format("BVH max_leaf_size {} is outside 1..{}", s.max_leaf_size,
                                 gpu::kBvhMaxLeafSize));
  if (s.bins < 2 || s.bins > 256)
    throw InputError(fmt::format("BVH bins {} is outside 2..256", s.bins));
  if (!(s.traversal_cost >= 0.0f) || !(s.triangle_cost > 0.0f))
    throw InputError(
        fmt::format("BVH costs must be traversal_cost >= 0 and triangle_cost > 0 (got {} and {})",
                    s.traversal_cost, s.triangle_cost));
  if (s.max_depth < 1 || s.max_depth > gpu::kBvhStackSize)
    throw InputError(fmt::format("BVH max_depth {} is outside 1..{} (the traversal's stack)",
                                 s.max_depth, gpu::kBvhStackSize));
  if (triangles > std::size_t(gpu::kBvhMaxTriangles))
    throw InputError(fmt::format("the BVH holds at most {} triangles; the scene has {}",
                                 gpu::kBvhMaxTriangles, triangles));
  const int needed = std::max(1, medianLevels(triangles, s.max_leaf_size));
  if (needed > s.max_depth)
    throw InputError(
        fmt::format("BVH max_depth {} is too small for {} triangles at {} a leaf; give at least {}",
                    s.max_depth, triangles, s.max_leaf_size, needed));
}

}  // namespace

Bvh buildBvh(const IvmTriangleSet& set, const BvhSettings& settings) {
  checkSettings(settings, set.size());
  Bvh bvh;
  Builder(set, settings, bvh).build();
  return bvh;
}

gpu::RayCastHit castBvh(const Bvh& bvh, const IvmTriangleSet& set, const glm::vec3& o,
                        const glm::vec3& d, float t_min, float t_max) {
  gpu::RayCastHit hit = noRayHit();
  hit.t = t_max;
  const glm::vec3 inv_d = gpu::bvhInverseDirection(d);
  std::array<std::uint32_t, gpu::kBvhStackSize> stack;
  int depth = 0;
  std::uint32_t reference = gpu::kBvhRootReference;
  const auto finish = [&] {
    if (hit.triangle == gpu::kNoRayTriangle) hit.t = gpu::kRayInfinity;
    return hit;
  };
  for (;;) {
    // Inner nodes: both children's boxes from one node; into the nearer one hit, the farther
    // one hit kept on the stack.
    while (!gpu::bvhIsLeaf(reference)) {
      const glm::vec4* node = &bvh.nodes[std::size_t(reference) * gpu::kBvhNodeTexels];
      const glm::vec2 span0 =
          gpu::bvhBoxSpan(glm::vec3(node[0]), glm::vec3(node[1]), o, inv_d, t_min, hit.t);
      const glm::vec2 span1 =
          gpu::bvhBoxSpan(glm::vec3(node[2]), glm::vec3(node[3]), o, inv_d, t_min, hit.t);
      const bool enter0 = span0.x <= span0.y, enter1 = span1.x <= span1.y;
      const std::uint32_t child0 = std::bit_cast<std::uint32_t>(node[0].w);
      const std::uint32_t child1 = std::bit_cast<std::uint32_t>(node[2].w);
      if (enter0 && enter1) {
        const bool second_nearer = span1.x < span0.x;
        if (depth == gpu::kBvhStackSize)
          throw std::logic_error("castBvh: the hierarchy is deeper than kBvhStackSize");
        stack[std::size_t(depth++)] = second_nearer ? child0 : child1;
        reference = second_nearer ? child1 : child0;
      } else if (enter0) {
        reference = child0;
      } else if (enter1) {
        reference = child1;
      } else {
        if (depth == 0) return finish();
        reference = stack[std::size_t(--depth)];
      }
    }
    // A leaf: its triangles, consecutive slots.
    const std::uint32_t first = gpu::bvhLeafFirst(reference);
    const std::uint32_t count = gpu::bvhLeafCount(reference);
    for (std::uint32_t slot = first; slot < first + count; ++slot)
      intersectIvmTriangle(set, bvh.triangle_order[slot], o, d, t_min, hit);
    if (depth == 0) return finish();
    reference = stack[std::size_t(--depth)];
  }
}

GpuBvh::GpuBvh(const IvmTriangleSet& set, const BvhSettings& settings)
    : bvh_(buildBvh(set, settings)), triangles_(set, bvh_.triangle_order) {
  checkRayCastingLimits(bvh_.nodes.size());
  nodes_buffer_ = gl::Buffer::fromVector(bvh_.nodes, 0);
  nodes_texture_ = gl::Texture::makeBuffer(GL_RGBA32F, nodes_buffer_);
}

void GpuBvh::bind() const {
  triangles_.bind();
  nodes_texture_.bind(GLuint(gpu::kRayNodesUnit));
}

}  // namespace gib::rt
