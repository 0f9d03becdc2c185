#include "realtime/atlas/atlas_layout.h"

#include "common/input_error.h"

#include <fmt/format.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <map>
#include <numeric>
#include <utility>

namespace gib::rt::atlas {

namespace {

// Two triangles are coplanar for chart purposes when their normals agree within ~2.6° and each
// vertex lies within this fraction of the scene's extent from the other's plane. Slightly bent
// quads (the Cornell box's left wall is one, by a few millimetres) stay one chart: each texel's
// area and sample point are computed on its own triangle, so flattening them costs nothing but
// a little texel stretch.
constexpr float kCoplanarCosine = 0.999f;
constexpr float kCoplanarDistance = 5e-3f;
// Triangles of a chart whose edges are tried as its axes (a chart's first ones; enough for the
// rectangles and polygons that planar charts are).
constexpr std::size_t kAxisCandidates = 16;

struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(int n) : parent(std::size_t(n)) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int i) {
    while (parent[std::size_t(i)] != i)
      i = parent[std::size_t(i)] = parent[std::size_t(parent[std::size_t(i)])];
    return i;
  }
  void unite(int a, int b) { parent[std::size_t(find(a))] = find(b); }
};

bool coplanar(const AtlasTriangle& a, const AtlasTriangle& b, float tolerance) {
  if (a.material != b.material || glm::dot(a.normal, b.normal) < kCoplanarCosine) return false;
  for (const glm::vec3& q : b.p)
    if (std::abs(glm::dot(a.normal, q - a.p[0])) > tolerance) return false;
  return true;
}

// Chart index of each triangle (−1 for degenerate ones): edge-connected coplanar triangles.
std::vector<int> groupCharts(const std::vector<AtlasTriangle>& triangles, int& chart_count) {
  glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
  for (const AtlasTriangle& t : triangles)
    for (const glm::vec3& q : t.p) lo = glm::min(lo, q), hi = glm::max(hi, q);
  const float tolerance = kCoplanarDistance * std::max(glm::length(hi - lo), 1e-6f);

  const int n = int(triangles.size());
  UnionFind sets(n);
  std::map<std::tuple<std::uint32_t, std::uint32_t, std::uint32_t>, int> edge_owner;
  for (int i = 0; i < n; ++i) {
    const AtlasTriangle& t = triangles[std::size_t(i)];
    if (t.area <= 0) continue;
    for (int e = 0; e < 3; ++e) {
      const std::uint32_t u = t.indices[e], v = t.indices[(e + 1) % 3];
      const auto key = std::make_tuple(t.mesh, std::min(u, v), std::max(u, v));
      const auto [it, inserted] = edge_owner.emplace(key, i);
      if (!inserted && coplanar(triangles[std::size_t(it->second)], t, tolerance))
        sets.unite(i, it->second);
    }
  }
  std::vector<int> chart(std::size_t(n), -1);
  std::map<int, int> index_of_root;
  for (int i = 0; i < n; ++i) {
    if (triangles[std::size_t(i)].area <= 0) continue;
    const auto [it, inserted] = index_of_root.emplace(sets.find(i), int(index_of_root.size()));
    chart[std::size_t(i)] = it->second;
  }
  chart_count = int(index_of_root.size());
  return chart;
}

// A chart laid flat in its plane: 2D coordinates of its triangles' vertices, origin at the
// bounding box's corner.
struct FlatChart {
  std::vector<int> triangles;
  std::vector<std::array<glm::vec2, 3>> points;
  glm::vec2 size{0.0f};
};

std::vector<FlatChart> flattenCharts(const std::vector<AtlasTriangle>& triangles,
                                     const std::vector<int>& chart_of, int chart_count) {
  std::vector<FlatChart> charts;
  charts.resize(std::size_t(chart_count));
  for (int i = 0; i < int(triangles.size()); ++i)
    if (chart_of[std::size_t(i)] >= 0)
      charts[std::size_t(chart_of[std::size_t(i)])].triangles.push_back(i);
  for (FlatChart& chart : charts) {
    // Axes: of the edge directions of the chart's first triangles, the one whose bounding box in
    // the plane has the least area (a rectangle made of two triangles lies axis-aligned, not
    // along its diagonal, which would waste half its texels).
    const AtlasTriangle& first = triangles[std::size_t(chart.triangles.front())];
    auto boxArea = [&](const glm::vec3& u, const glm::vec3& v) {
      glm::vec2 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
      for (int t : chart.triangles)
        for (const glm::vec3& q : triangles[std::size_t(t)].p) {
          const glm::vec2 flat(glm::dot(q - first.p[0], u), glm::dot(q - first.p[0], v));
          lo = glm::min(lo, flat), hi = glm::max(hi, flat);
        }
      return (hi.x - lo.x) * (hi.y - lo.y);
    };
    glm::vec3 u(0.0f);
    float best = std::numeric_limits<float>::max();
    const std::size_t candidates = std::min<std::size_t>(chart.triangles.size(), kAxisCandidates);
    for (std::size_t k = 0; k < candidates; ++k)
      for (int e = 0; e < 3; ++e) {
        const AtlasTriangle& t = triangles[std::size_t(chart.triangles[k])];
        const glm::vec3 d = t.p[(e + 1) % 3] - t.p[e];
        const glm::vec3 in_plane = d - first.normal * glm::dot(d, first.normal);
        if (glm::dot(in_plane, in_plane) <= 0) continue;
        const glm::vec3 axis = glm::normalize(in_plane);
        const float area = boxArea(axis, glm::cross(first.normal, axis));
        if (area < best) best = area, u = axis;
      }
    const glm::vec3 v = glm::cross(first.normal, u);
    glm::vec2 lo(std::numeric_limits<float>::max());
    for (int t : chart.triangles) {
      std::array<glm::vec2, 3> flat;
      for (int k = 0; k < 3; ++k) {
        const glm::vec3 d = triangles[std::size_t(t)].p[k] - first.p[0];
        flat[k] = {glm::dot(d, u), glm::dot(d, v)};
        lo = glm::min(lo, flat[k]);
      }
      chart.points.push_back(flat);
    }
    for (auto& flat : chart.points)
      for (glm::vec2& q : flat) {
        q -= lo;
        chart.size = glm::max(chart.size, q);
      }
  }
  return charts;
}

// Texels a chart of `size` scene units occupies at `scale`. A bilinear lookup at texel coordinate
// t reads texels floor(t − ½) and floor(t − ½) + 1. The chart's points span [g, g + c] with
// g = kGutterTexels and c = ceil(size·scale), so the lookups read texels g − 1 = 0 up to
// floor(g + c − ½) + 1 = g + c: a width of c + 2g holds them all.
glm::ivec2 rectSize(const glm::vec2& size, float scale) {
  const int gutters = 2 * kGutterTexels;
  return {int(std::ceil(size.x * scale)) + gutters, int(std::ceil(size.y * scale)) + gutters};
}

// Shelf packing, tallest first; false when the charts do not fit at this scale.
bool packCharts(const std::vector<FlatChart>& charts, float scale, int resolution,
                std::vector<ChartRect>& rects) {
  rects.assign(charts.size(), {});
  std::vector<int> order(charts.size());
  std::iota(order.begin(), order.end(), 0);
  std::vector<glm::ivec2> sizes;
  for (const FlatChart& c : charts) sizes.push_back(rectSize(c.size, scale));
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return sizes[std::size_t(a)].y > sizes[std::size_t(b)].y; });
  int x = 0, y = 0, shelf = 0;
  for (int i : order) {
    const glm::ivec2 s = sizes[std::size_t(i)];
    if (s.x > resolution) return false;
    if (x + s.x > resolution) x = 0, y += shelf, shelf = 0;
    if (y + s.y > resolution) return false;
    rects[std::size_t(i)] = {x, y, s.x, s.y};
    x += s.x;
    shelf = std::max(shelf, s.y);
  }
  return true;
}

double triangleArea2d(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
  return 0.5 * ((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y));
}

// The part of the unit texel square at `corner` inside the counter-clockwise triangle `t`
// (Sutherland–Hodgman against the triangle's three edges).
std::vector<glm::dvec2> clipSquare(const glm::dvec2& corner, const std::array<glm::dvec2, 3>& t) {
  std::vector<glm::dvec2> polygon = {corner, corner + glm::dvec2(1, 0), corner + glm::dvec2(1, 1),
                                     corner + glm::dvec2(0, 1)};
  for (int e = 0; e < 3 && !polygon.empty(); ++e) {
    const glm::dvec2 a = t[std::size_t(e)], b = t[std::size_t((e + 1) % 3)];
    auto side = [&](const glm::dvec2& q) {
      return (b.x - a.x) * (q.y - a.y) - (b.y - a.y) * (q.x - a.x);
    };
    std::vector<glm::dvec2> out;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
      const glm::dvec2 p = polygon[i], q = polygon[(i + 1) % polygon.size()];
      const double sp = side(p), sq = side(q);
      if (sp >= 0) out.push_back(p);
      if ((sp >= 0) != (sq >= 0)) out.push_back(p + (q - p) * (sp / (sp - sq)));
    }
    polygon = std::move(out);
  }
  return polygon;
}

// Area and centroid of a simple polygon.
std::pair<double, glm::dvec2> areaCentroid(const std::vector<glm::dvec2>& polygon) {
  double area = 0;
  glm::dvec2 centroid(0.0);
  for (std::size_t i = 1; i + 1 < polygon.size(); ++i) {
    const double a = triangleArea2d(polygon[0], polygon[i], polygon[i + 1]);
    area += a;
    centroid += a * (polygon[0] + polygon[i] + polygon[i + 1]) / 3.0;
  }
  return {area, area > 0 ? centroid / area : glm::dvec2(0.0)};
}

}  // namespace

std::vector<AtlasTriangle> atlasTriangles(const scene::Scene& scene) {
  std::vector<AtlasTriangle> triangles;
  for (std::uint32_t m = 0; m < scene.meshes.size(); ++m) {
    const scene::Mesh& mesh = scene.meshes[m];
    for (const glm::uvec3& t : mesh.triangles) {
      AtlasTriangle tri;
      tri.p = {mesh.positions[t.x], mesh.positions[t.y], mesh.positions[t.z]};
      const glm::vec3 cross = glm::cross(tri.p[1] - tri.p[0], tri.p[2] - tri.p[0]);
      const float length = glm::length(cross);
      tri.area = 0.5f * length;
      tri.normal = length > 0 ? cross / length : glm::vec3(0.0f);
      tri.material = mesh.material;
      tri.mesh = m;
      tri.indices = t;
      triangles.push_back(tri);
    }
  }
  return triangles;
}

AtlasLayout layoutAtlas(const std::vector<AtlasTriangle>& triangles, int resolution) {
  AtlasLayout layout;
  layout.resolution = resolution;
  int chart_count = 0;
  layout.chart_of_triangle = groupCharts(triangles, chart_count);
  const std::vector<FlatChart> charts =
      flattenCharts(triangles, layout.chart_of_triangle, chart_count);
  layout.texel_coordinates.assign(triangles.size(), {});
  if (charts.empty()) return layout;

  // The largest scale at which the charts fit, by bisection: no scale above sqrt(R² / area) can
  // fit, and the smallest useful one gives every chart one texel inside its gutter.
  double total_area = 0;
  for (const AtlasTriangle& t : triangles) total_area += t.area;
  double hi = std::sqrt(double(resolution) * resolution / std::max(total_area, 1e-30));
  double lo = 1e-9 * hi;
  std::vector<ChartRect> rects;
  if (!packCharts(charts, float(lo), resolution, rects))
    throw InputError(fmt::format(
        "the scene's {} planar charts do not fit a {}x{} atlas even at one texel each; choose a "
        "larger atlas (--set atlas=...)",
        charts.size(), resolution, resolution));
  for (int i = 0; i < 40; ++i) {
    const double mid = 0.5 * (lo + hi);
    (packCharts(charts, float(mid), resolution, rects) ? lo : hi) = mid;
  }
  packCharts(charts, float(lo), resolution, rects);
  layout.texels_per_unit = float(lo);
  layout.charts = rects;

  for (std::size_t c = 0; c < charts.size(); ++c) {
    const glm::vec2 origin(float(rects[c].x + kGutterTexels), float(rects[c].y + kGutterTexels));
    for (std::size_t k = 0; k < charts[c].triangles.size(); ++k) {
      auto& uv = layout.texel_coordinates[std::size_t(charts[c].triangles[k])];
      for (int v = 0; v < 3; ++v)
        uv[std::size_t(v)] = origin + charts[c].points[k][std::size_t(v)] * layout.texels_per_unit;
    }
  }
  return layout;
}

AtlasTexels bakeAtlasTexels(const std::vector<AtlasTriangle>& triangles,
                            const AtlasLayout& layout) {
  const int r = layout.resolution;
  AtlasTexels baked;
  baked.resolution = r;
  baked.texels.assign(std::size_t(r) * std::size_t(r), {});
  std::vector<int> chart_of_texel(baked.texels.size(), -1);
  for (std::size_t c = 0; c < layout.charts.size(); ++c) {
    const ChartRect& rect = layout.charts[c];
    for (int y = rect.y; y < rect.y + rect.height; ++y)
      for (int x = rect.x; x < rect.x + rect.width; ++x)
        chart_of_texel[std::size_t(y * r + x)] = int(c);
  }

  // Step 1: exact coverage. Each triangle adds the area of each texel square it overlaps, and
  // the centroid of that overlap mapped back to world space through barycentric coordinates.
  std::vector<double> best_share(baked.texels.size(), 0.0);
  std::vector<glm::dvec3> centroid_sum(baked.texels.size(), glm::dvec3(0.0));
  std::vector<glm::dvec3> normal_sum(baked.texels.size(), glm::dvec3(0.0));
  std::vector<double> area_sum(baked.texels.size(), 0.0);
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    if (layout.chart_of_triangle[t] < 0) continue;
    const AtlasTriangle& tri = triangles[t];
    std::array<glm::dvec2, 3> uv;
    for (int k = 0; k < 3; ++k)
      uv[std::size_t(k)] = glm::dvec2(layout.texel_coordinates[t][std::size_t(k)]);
    double uv_area = triangleArea2d(uv[0], uv[1], uv[2]);
    if (uv_area < 0) std::swap(uv[1], uv[2]);  // clipping wants counter-clockwise
    std::array<glm::dvec3, 3> world = {glm::dvec3(tri.p[0]), glm::dvec3(tri.p[1]),
                                       glm::dvec3(tri.p[2])};
    if (uv_area < 0) std::swap(world[1], world[2]), uv_area = -uv_area;
    if (uv_area <= 0) continue;
    const double world_per_uv = double(tri.area) / uv_area;  // exact even for a slightly bent chart
    const glm::dvec2 lo = glm::min(uv[0], glm::min(uv[1], uv[2]));
    const glm::dvec2 hi = glm::max(uv[0], glm::max(uv[1], uv[2]));
    for (int y = std::max(0, int(std::floor(lo.y))); y <= std::min(r - 1, int(std::floor(hi.y)));
         ++y)
      for (int x = std::max(0, int(std::floor(lo.x))); x <= std::min(r - 1, int(std::floor(hi.x)));
           ++x) {
        const auto [area, centroid] = areaCentroid(clipSquare(glm::dvec2(x, y), uv));
        if (area <= 0) continue;
        const double b1 = triangleArea2d(uv[0], centroid, uv[2]) / uv_area;
        const double b2 = triangleArea2d(uv[0], uv[1], centroid) / uv_area;
        const glm::dvec3 point = world[0] + b1 * (world[1] - world[0]) + b2 * (world[2] - world[0]);
        const std::size_t i = std::size_t(y * r + x);
        const double world_area = area * world_per_uv;
        area_sum[i] += world_area;
        centroid_sum[i] += world_area * point;
        normal_sum[i] += world_area * glm::dvec3(tri.normal);
        if (world_area > best_share[i])
          best_share[i] = world_area, baked.texels[i].triangle = int(t);
      }
  }
  std::deque<int> frontier;
  for (std::size_t i = 0; i < baked.texels.size(); ++i) {
    if (area_sum[i] <= 0) continue;
    AtlasTexel& texel = baked.texels[i];
    texel.area = float(area_sum[i]);
    texel.position = glm::vec3(centroid_sum[i] / area_sum[i]);
    texel.normal = glm::vec3(glm::normalize(normal_sum[i]));
    ++baked.covered;
    frontier.push_back(int(i));
  }

  // Step 2: dilation. Breadth first from the covered texels, every gutter texel of a chart's
  // rectangle takes the sample point of its nearest covered texel of the same chart (area 0).
  while (!frontier.empty()) {
    const int i = frontier.front();
    frontier.pop_front();
    const int x = i % r, y = i / r;
    for (const glm::ivec2 d :
         {glm::ivec2(1, 0), glm::ivec2(-1, 0), glm::ivec2(0, 1), glm::ivec2(0, -1),
          glm::ivec2(1, 1), glm::ivec2(-1, 1), glm::ivec2(1, -1), glm::ivec2(-1, -1)}) {
      const int nx = x + d.x, ny = y + d.y;
      if (nx < 0 || ny < 0 || nx >= r || ny >= r) continue;
      const int j = ny * r + nx;
      if (chart_of_texel[std::size_t(j)] != chart_of_texel[std::size_t(i)] ||
          baked.texels[std::size_t(j)].inChart())
        continue;
      baked.texels[std::size_t(j)] = baked.texels[std::size_t(i)];
      baked.texels[std::size_t(j)].area = 0;
      frontier.push_back(j);
    }
  }
  return baked;
}

}  // namespace gib::rt::atlas
