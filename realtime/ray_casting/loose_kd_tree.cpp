#include "realtime/ray_casting/loose_kd_tree.h"

#include "common/input_error.h"

#include <fmt/format.h>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/packing.hpp>
#include <glm/vec2.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace gib::rt {

namespace {

// Every cell plane is moved outward by this fraction of the root's diagonal before it is rounded
// to a half. A ray that hits a triangle must visit its leaf, but the hit and the cell's segment
// are computed apart: the IVM test accepts points up to kIvmEdgeTolerance (10⁻⁵) of the
// triangle's size outside it, and (plane − o)·(1/d) rounds (a few ulps; GLSL's reciprocal is
// looser). Without the margin a ray through a vertex on a cell's face could find the hit by brute
// force and miss the leaf here. 4·10⁻⁵ of the diagonal covers the edge tolerance four times over,
// the test's rounding term (kIvmRoundingTolerance: 4·10⁻⁶ of the origin's distance) for origins
// within ten diagonals, and the rounding of t for origins within ~100 diagonals of the scene; the
// cells grow by less than the halves' own rounding already makes them.
constexpr float kCellSlackFraction = 4e-5f;

constexpr std::uint16_t kHalfPlusInfinity = 0x7c00;
constexpr std::uint16_t kHalfMinusInfinity = 0xfc00;
constexpr float kHalfMax = 65504.0f;

std::uint16_t halfBits(float v) {
  return std::uint16_t(glm::packHalf2x16(glm::vec2(v, 0.0f)));
}
float halfValue(std::uint16_t h) {
  return glm::unpackHalf2x16(std::uint32_t(h)).x;
}
// The neighbouring half above / below (zero of either sign steps to the smallest denormal).
std::uint16_t halfAbove(std::uint16_t h) {
  if ((h & 0x7fff) == 0) return 0x0001;
  return (h & 0x8000) ? std::uint16_t(h - 1) : std::uint16_t(h + 1);
}
std::uint16_t halfBelow(std::uint16_t h) {
  if ((h & 0x7fff) == 0) return 0x8001;
  return (h & 0x8000) ? std::uint16_t(h + 1) : std::uint16_t(h - 1);
}

// The least half ≥ v and the greatest half ≤ v (packHalf2x16 rounds to nearest, or truncates in
// some implementations: either way the loops move it at most a step). Beyond the halves' range
// the bound becomes ±∞ or ±65504, still on the safe side.
std::uint16_t roundHalfUp(float v) {
  if (v > kHalfMax) return kHalfPlusInfinity;
  if (v < -kHalfMax) return halfBits(-kHalfMax);
  std::uint16_t h = halfBits(v);
  while (halfValue(h) < v) h = halfAbove(h);
  while (halfValue(halfBelow(h)) >= v) h = halfBelow(h);
  return h;
}
std::uint16_t roundHalfDown(float v) {
  if (v < -kHalfMax) return kHalfMinusInfinity;
  if (v > kHalfMax) return halfBits(kHalfMax);
  std::uint16_t h = halfBits(v);
  while (halfValue(h) > v) h = halfBelow(h);
  while (halfValue(halfAbove(h)) <= v) h = halfAbove(h);
  return h;
}

float surfaceArea(const glm::vec3& lo, const glm::vec3& hi) {
  const glm::vec3 e = glm::max(hi - lo, glm::vec3(0.0f));
  return 2.0f * (e.x * e.y + e.y * e.z + e.z * e.x);
}

// Median splits needed to bring n triangles to leaves the layout can hold.
int levelsToLeafSize(std::size_t n) {
  int levels = 0;
  for (std::size_t cap = gpu::kLooseKdMaxLeafTriangles; cap < n; cap *= 2) ++levels;
  return levels;
}

// The tree as the builder makes it, before it is packed.
struct BuildNode {
  int axis = -1;  // −1: a leaf
  float left_max = 0.0f, right_min = 0.0f;
  bool left_empty = false, right_empty = false;
  std::uint32_t child[2] = {0, 0};
  std::uint32_t start = 0, count = 0;  // a leaf's slots
};

class Builder {
 public:
  Builder(const IvmTriangleSet& set, const LooseKdTreeSettings& settings)
      : settings_(settings), n_(set.size()) {
    lo_.resize(n_);
    hi_.resize(n_);
    centre_.resize(n_);
    for (std::size_t i = 0; i < n_; ++i) {
      const IvmTriangle& t = set.triangles[i];
      lo_[i] = glm::min(t.a, glm::min(t.b, t.c));
      hi_[i] = glm::max(t.a, glm::max(t.b, t.c));
      centre_[i] = 0.5f * (lo_[i] + hi_[i]);
    }
    slack_ = kCellSlackFraction * glm::length(set.bounds_max - set.bounds_min);
    // One list per axis, sorted by the centre of the triangles' bounds along it (ties by index,
    // so the order is total and the build deterministic). A cut takes a prefix of one list; the
    // other two are partitioned stably, so every list stays sorted within each cell.
    for (int a = 0; a < 3; ++a) {
      order_[a].resize(n_);
      for (std::size_t i = 0; i < n_; ++i) order_[a][i] = std::uint32_t(i);
      std::sort(order_[a].begin(), order_[a].end(), [&](std::uint32_t x, std::uint32_t y) {
        return centre_[x][a] < centre_[y][a] || (centre_[x][a] == centre_[y][a] && x < y);
      });
    }
    left_side_.assign(n_, 0);
    prefix_max_.resize(n_ + 1);
    suffix_min_.resize(n_ + 1);
    root_lo_ = set.bounds_min - glm::vec3(slack_);
    root_hi_ = set.bounds_max + glm::vec3(slack_);
    root_area_ = std::max(surfaceArea(root_lo_, root_hi_), std::numeric_limits<float>::min());
  }

  void build(LooseKdTree& tree) {
    build(0, n_, root_lo_, root_hi_, 0, tree);
    tree.triangle_order = order_[0];
  }
  const std::vector<BuildNode>& nodes() const { return nodes_; }

 private:
  struct Cut {
    int axis = -1;
    std::size_t left = 0;  // triangles in the left child
    float cost = std::numeric_limits<float>::max();
  };

  // The planes of the cut of [begin, begin + n) along `axis` with `left` triangles on the left
  // (prefix_max_ and suffix_min_ filled for that axis): the left child's maximum and the right
  // child's minimum, each moved out by the slack and kept inside the cell.
  std::pair<float, float> planes(std::size_t n, std::size_t left, int axis, const glm::vec3& lo,
                                 const glm::vec3& hi) const {
    const float left_max = left > 0 ? std::min(hi[axis], prefix_max_[left] + slack_) : lo[axis];
    const float right_min = left < n ? std::max(lo[axis], suffix_min_[left] - slack_) : hi[axis];
    return {left_max, right_min};
  }

  void scanAxis(std::size_t begin, std::size_t n, int axis) {
    const std::vector<std::uint32_t>& order = order_[axis];
    prefix_max_[0] = -std::numeric_limits<float>::max();
    for (std::size_t i = 0; i < n; ++i)
      prefix_max_[i + 1] = std::max(prefix_max_[i], hi_[order[begin + i]][axis]);
    suffix_min_[n] = std::numeric_limits<float>::max();
    for (std::size_t i = n; i-- > 0;)
      suffix_min_[i] = std::min(suffix_min_[i + 1], lo_[order[begin + i]][axis]);
  }

  // The SAH's best cut of the cell whose children may hold at most `child_cap` triangles each
  // (the depth bound), over every prefix of every axis's order, empty prefixes included (a cut
  // with one empty side trims empty space off the cell: Fig. 5.10's empty leaves).
  Cut bestSahCut(std::size_t begin, std::size_t n, const glm::vec3& lo, const glm::vec3& hi,
                 std::size_t child_cap) {
    Cut best;
    const float area = std::max(surfaceArea(lo, hi), std::numeric_limits<float>::min());
    const std::size_t first = n > child_cap ? n - child_cap : 0;
    const std::size_t last = std::min(n, child_cap);
    for (int axis = 0; axis < 3; ++axis) {
      scanAxis(begin, n, axis);
      for (std::size_t left = first; left <= last; ++left) {
        const auto [left_max, right_min] = planes(n, left, axis, lo, hi);
        glm::vec3 left_hi = hi, right_lo = lo;
        left_hi[axis] = left_max;
        right_lo[axis] = right_min;
        const float area_left = left > 0 ? surfaceArea(lo, left_hi) : 0.0f;
        const float area_right = left < n ? surfaceArea(right_lo, hi) : 0.0f;
        const float cost =
            settings_.traversal_cost + (area_left * float(left) + area_right * float(n - left)) /
                                           area * settings_.intersection_cost;
        if (cost < best.cost) best = {axis, left, cost};
      }
    }
    return best;
  }

  // The median of the axis along which the cell's triangles' centres spread most.
  Cut medianCut(std::size_t begin, std::size_t n) const {
    int axis = 0;
    float spread = -1.0f;
    for (int a = 0; a < 3; ++a) {
      const float s =
          centre_[order_[a][begin + n - 1]][a] - centre_[order_[a][begin]][a];  // sorted
      if (s > spread) {
        spread = s;
        axis = a;
      }
    }
    return {axis, n / 2, 0.0f};
  }

  std::uint32_t makeLeaf(std::size_t begin, std::size_t n, const glm::vec3& lo, const glm::vec3& hi,
                         int depth, LooseKdTree& tree) {
    BuildNode leaf;
    leaf.start = std::uint32_t(begin);
    leaf.count = std::uint32_t(n);
    nodes_.push_back(leaf);
    tree.max_depth = std::max(tree.max_depth, depth);
    tree.max_leaf_triangles = std::max(tree.max_leaf_triangles, int(n));
    tree.sah_cost += surfaceArea(lo, hi) / root_area_ * double(n) * settings_.intersection_cost;
    return std::uint32_t(nodes_.size() - 1);
  }

  std::uint32_t build(std::size_t begin, std::size_t n, const glm::vec3& lo, const glm::vec3& hi,
                      int depth, LooseKdTree& tree) {
    // Step 1: a leaf when the cell is small enough or at the depth bound (where the bound
    // guarantees n ≤ 255: see child_cap).
    if (n <= std::size_t(settings_.max_leaf_triangles) || depth == settings_.max_depth)
      return makeLeaf(begin, n, lo, hi, depth, tree);

    // Step 2: the SAH's best cut whose children can still be split into leaves of at most 255
    // triangles by medians before the depth bound: 255·2^(levels left below them).
    const int levels_below = settings_.max_depth - depth - 1;
    const std::size_t child_cap =
        levels_below >= 24 ? n : std::size_t(gpu::kLooseKdMaxLeafTriangles) << levels_below;
    Cut cut = bestSahCut(begin, n, lo, hi, child_cap);
    const float leaf_cost = float(n) * settings_.intersection_cost;
    // Step 3: keep the cell as a leaf when no cut beats it, unless it holds more than a leaf
    // may; then split it at the median anyway (always within child_cap: the root's check and
    // this rule keep depth + levelsToLeafSize(n) ≤ max_depth at every node).
    if (!(cut.cost < leaf_cost)) {
      if (n <= std::size_t(gpu::kLooseKdMaxLeafTriangles))
        return makeLeaf(begin, n, lo, hi, depth, tree);
      cut = medianCut(begin, n);
      ++tree.median_splits;
    }

    // Step 4: the planes, and the triangles sorted into the children, every axis's list kept
    // sorted within each.
    scanAxis(begin, n, cut.axis);
    const auto [left_max, right_min] = planes(n, cut.left, cut.axis, lo, hi);
    const std::vector<std::uint32_t>& by_axis = order_[cut.axis];
    for (std::size_t i = 0; i < n; ++i) left_side_[by_axis[begin + i]] = i < cut.left ? 1 : 0;
    for (int a = 0; a < 3; ++a)
      if (a != cut.axis)
        std::stable_partition(order_[a].begin() + std::ptrdiff_t(begin),
                              order_[a].begin() + std::ptrdiff_t(begin + n),
                              [&](std::uint32_t t) { return left_side_[t] != 0; });

    BuildNode node;
    node.axis = cut.axis;
    node.left_max = left_max;
    node.right_min = right_min;
    node.left_empty = cut.left == 0;
    node.right_empty = cut.left == n;
    nodes_.push_back(node);
    const std::uint32_t index = std::uint32_t(nodes_.size() - 1);
    ++tree.cut_nodes;
    tree.sah_cost += surfaceArea(lo, hi) / root_area_ * settings_.traversal_cost;

    // Step 5: the children, left then right, so that leaves take consecutive slots in order.
    glm::vec3 left_hi = hi, right_lo = lo;
    left_hi[cut.axis] = left_max;
    right_lo[cut.axis] = right_min;
    const std::uint32_t left = build(begin, cut.left, lo, left_hi, depth + 1, tree);
    const std::uint32_t right =
        build(begin + cut.left, n - cut.left, right_lo, hi, depth + 1, tree);
    nodes_[index].child[0] = left;
    nodes_[index].child[1] = right;
    return index;
  }

  const LooseKdTreeSettings& settings_;
  std::size_t n_;
  std::vector<glm::vec3> lo_, hi_, centre_;
  std::array<std::vector<std::uint32_t>, 3> order_;
  std::vector<std::uint8_t> left_side_;
  std::vector<float> prefix_max_, suffix_min_;
  float slack_ = 0.0f;
  glm::vec3 root_lo_{0.0f}, root_hi_{0.0f};
  float root_area_ = 1.0f;
  std::vector<BuildNode> nodes_;
};

// Packs the built nodes into blocks (Fig. 5.13): each block is filled from its node 0 down its
// levels; a cut that falls on a block's last level becomes a pointer slot and the root of a new
// block, blocks numbered in the order they are opened (breadth first over blocks).
class Packer {
 public:
  Packer(const std::vector<BuildNode>& built, LooseKdTree& tree)
      : built_(built),
        tree_(tree),
        stride_(std::size_t{1} << tree.block_levels),
        first_last_level_((std::size_t{1} << (tree.block_levels - 1)) - 1) {}

  void pack() {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> pending = {{0u, openBlock()}};
    for (std::size_t i = 0; i < pending.size(); ++i) {
      const auto [node, block] = pending[i];
      place(node, std::size_t(block) * stride_, 0, pending);
    }
    tree_.blocks = tree_.nodes.size() / stride_;
  }

 private:
  std::uint32_t openBlock() {
    const std::size_t block = tree_.nodes.size() / stride_;
    // Unused slots are empty leaves: nothing reaches them, and if something did it would find
    // no triangles.
    tree_.nodes.resize(tree_.nodes.size() + stride_, gpu::looseKdLeafWord(0u, 0u));
    tree_.flags.resize(tree_.flags.size() + stride_, std::uint8_t(gpu::kLooseKdLeafFlag));
    return std::uint32_t(block);
  }

  void place(std::uint32_t node, std::size_t block_start, std::size_t in_block,
             std::vector<std::pair<std::uint32_t, std::uint32_t>>& pending) {
    const BuildNode& b = built_[node];
    const std::size_t slot = block_start + in_block;
    if (b.axis < 0) {
      tree_.nodes[slot] = gpu::looseKdLeafWord(b.start, b.count);
      tree_.flags[slot] = std::uint8_t(gpu::kLooseKdLeafFlag);
      if (b.count > 0) {
        ++tree_.leaves;
      } else {
        ++tree_.empty_leaves;
      }
      return;
    }
    tree_.flags[slot] = std::uint8_t(b.axis);
    if (in_block >= first_last_level_) {
      const std::uint32_t target = openBlock();
      tree_.nodes[slot] = target;
      ++tree_.pointer_slots;
      pending.emplace_back(node, target);
      return;
    }
    const std::uint32_t low = b.left_empty ? kHalfMinusInfinity : roundHalfUp(b.left_max);
    const std::uint32_t high = b.right_empty ? kHalfPlusInfinity : roundHalfDown(b.right_min);
    tree_.nodes[slot] = low | (high << 16);
    place(b.child[0], block_start, 2 * in_block + 1, pending);
    place(b.child[1], block_start, 2 * in_block + 2, pending);
  }

  const std::vector<BuildNode>& built_;
  LooseKdTree& tree_;
  std::size_t stride_, first_last_level_;
};

void checkSettings(const LooseKdTreeSettings& s) {
  if (s.max_leaf_triangles < 1 || s.max_leaf_triangles > gpu::kLooseKdMaxLeafTriangles)
    throw std::invalid_argument(fmt::format("loose kd-tree: max_leaf_triangles {} outside 1..{}",
                                            s.max_leaf_triangles, gpu::kLooseKdMaxLeafTriangles));
  if (!(s.traversal_cost > 0.0f) || !(s.intersection_cost > 0.0f))
    throw std::invalid_argument("loose kd-tree: the SAH costs must be positive");
  if (s.block_levels < 2 || s.block_levels > 16)
    throw std::invalid_argument(
        fmt::format("loose kd-tree: block_levels {} outside 2..16", s.block_levels));
  if (s.max_depth < 1 || s.max_depth > gpu::kLooseKdMaxDepth)
    throw std::invalid_argument(fmt::format("loose kd-tree: max_depth {} outside 1..{}",
                                            s.max_depth, gpu::kLooseKdMaxDepth));
}

}  // namespace

LooseKdTree buildLooseKdTree(const IvmTriangleSet& set, const LooseKdTreeSettings& settings) {
  checkSettings(settings);
  if (set.size() > std::size_t(gpu::kLooseKdMaxTriangles))
    throw InputError(fmt::format(
        "the loose kd-tree addresses at most {} triangles (24-bit leaf starts) and the scene has "
        "{}; cast rays through the bvh instead",
        gpu::kLooseKdMaxTriangles, set.size()));
  if (levelsToLeafSize(set.size()) > settings.max_depth)
    throw std::invalid_argument(
        fmt::format("loose kd-tree: {} triangles need leaves deeper than max_depth {} allows",
                    set.size(), settings.max_depth));
  LooseKdTree tree;
  tree.block_levels = settings.block_levels;
  Builder builder(set, settings);
  builder.build(tree);
  Packer(builder.nodes(), tree).pack();
  if (tree.leaves > 0) tree.mean_leaf_triangles = double(set.size()) / double(tree.leaves);
  return tree;
}

gpu::RayCastHit castLooseKdTree(const LooseKdTree& tree, const IvmTriangleSet& set,
                                const glm::vec3& o, const glm::vec3& d, float t_min, float t_max) {
  // The shader's algorithm step by step (loose_kd_tree.glsl), with the block arithmetic of the
  // tree's own block_levels (the shader's is gpu::kLooseKdBlockLevels).
  const std::uint32_t levels = std::uint32_t(tree.block_levels);
  const std::uint32_t stride_mask = (1u << levels) - 1u;
  const std::uint32_t first_last_level = (1u << (levels - 1u)) - 1u;
  const glm::vec3 inv_d = 1.0f / d;

  gpu::RayCastHit hit = noRayHit();
  hit.t = t_max;
  struct Entry {
    std::uint32_t node;
    glm::vec2 segment;
  };
  std::array<Entry, gpu::kLooseKdMaxDepth> stack;
  int top = 0;
  std::uint32_t node = 0;
  glm::vec2 segment(t_min, t_max);
  for (;;) {
    if (segment.x <= segment.y) {
      const std::uint32_t flag = tree.flags[node];
      if (flag != gpu::kLooseKdLeafFlag) {
        // A cut: follow a pointer slot to its block's node 0, then split the segment.
        if ((node & stride_mask) >= first_last_level) node = tree.nodes[node] << levels;
        const glm::vec2 planes = gpu::looseKdCutPlanes(tree.nodes[node]);
        const int a = int(flag);
        const glm::vec4 s = gpu::looseKdChildSegments(planes, o[a], d[a], inv_d[a], segment);
        const std::uint32_t in_block = node & stride_mask;
        const std::uint32_t left = node - in_block + 2u * in_block + 1u;
        const bool near_is_left = gpu::looseKdNearIsLeft(d[a]);
        const std::uint32_t near_child = near_is_left ? left : left + 1u;
        const std::uint32_t far_child = near_is_left ? left + 1u : left;
        if (s.x <= s.y) {
          if (s.z <= s.w) {
            if (top == gpu::kLooseKdMaxDepth)
              throw std::logic_error("loose kd-tree: the traversal stack overflowed");
            stack[std::size_t(top++)] = {far_child, glm::vec2(s.z, s.w)};
          }
          node = near_child;
          segment = glm::vec2(s.x, s.y);
        } else {
          node = far_child;
          segment = glm::vec2(s.z, s.w);
        }
        continue;
      }
      // A leaf: every triangle over the whole ray (each lies wholly in this cell, so a hit here
      // is a hit of the ray; a nearer one may still lie in a cell not yet visited, which the
      // clamped segments below leave for the traversal to find).
      const std::uint32_t word = tree.nodes[node];
      const std::uint32_t start = gpu::looseKdLeafStart(word);
      const std::uint32_t end = start + gpu::looseKdLeafCount(word);
      for (std::uint32_t slot = start; slot < end; ++slot)
        intersectIvmTriangle(set, tree.triangle_order[slot], o, d, t_min, hit);
    }
    // Pop the next far child; nothing beyond the best hit needs visiting.
    if (top == 0) break;
    const Entry& e = stack[std::size_t(--top)];
    node = e.node;
    segment = glm::vec2(e.segment.x, std::min(e.segment.y, hit.t));
  }
  if (hit.triangle == gpu::kNoRayTriangle) hit.t = gpu::kRayInfinity;
  return hit;
}

GpuLooseKdTree::GpuLooseKdTree(const IvmTriangleSet& set, const LooseKdTreeSettings& settings)
    : tree_(buildLooseKdTree(set, settings)), triangles_(set, tree_.triangle_order) {
  if (tree_.block_levels != gpu::kLooseKdBlockLevels)
    throw std::invalid_argument(
        fmt::format("loose kd-tree: the shader reads blocks of {} levels (kLooseKdBlockLevels), "
                    "the tree has {}",
                    gpu::kLooseKdBlockLevels, tree_.block_levels));
  checkRayCastingLimits(tree_.nodes.size());
  node_buffer_ = gl::Buffer::fromVector(tree_.nodes, 0);
  flag_buffer_ = gl::Buffer::fromVector(tree_.flags, 0);
  nodes_ = gl::Texture::makeBuffer(GL_R32UI, node_buffer_);
  flags_ = gl::Texture::makeBuffer(GL_R8UI, flag_buffer_);
}

void GpuLooseKdTree::bind() const {
  triangles_.bind();
  nodes_.bind(GLuint(gpu::kRayNodesUnit));
  flags_.bind(GLuint(gpu::kRayFlagsUnit));
}

std::size_t GpuLooseKdTree::bytes() const {
  return triangles_.bytes() + node_buffer_.bytes() + flag_buffer_.bytes();
}

}  // namespace gib::rt
