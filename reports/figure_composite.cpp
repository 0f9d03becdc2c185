#include "reports/figure_composite.h"

#include "common/input_error.h"
#include "image/display_png.h"
#include "reports/figure_panels.h"

#include <algorithm>
#include <vector>

namespace gib::reports {

namespace {

namespace fs = std::filesystem;

struct Tile {
  int row = 0, column = 0;  // 0-based
  image::DisplayPicture picture;
};

// Pixel offsets of each column (or row) from its sizes, with the gap between neighbours.
std::vector<int> offsets(const std::vector<int>& sizes) {
  std::vector<int> starts;
  int at = 0;
  for (int size : sizes) {
    starts.push_back(at);
    at += size + kFigureGapPixels;
  }
  return starts;
}

int total(const std::vector<int>& sizes) {
  int sum = 0;
  for (int size : sizes) sum += size;
  return sizes.empty() ? 0 : sum + kFigureGapPixels * (int(sizes.size()) - 1);
}

}  // namespace

bool writeFigurePng(const fs::path& run_dir, const results::RunResults& results,
                    const results::FigureSpec& figure, const fs::path& target) {
  std::vector<Tile> tiles;
  int rows = 0;
  for (const results::FigureSpec::Panel& panel : figure.panels) {
    rows = std::max(rows, panel.row);
    const PanelPicture source = panelPicture(run_dir, results, panel);
    if (source.path.empty()) continue;
    const fs::path file =
        fs::path(source.path).is_absolute() ? fs::path(source.path) : run_dir / source.path;
    try {
      tiles.push_back({panel.row - 1, panel.column - 1, image::readDisplayPng(file)});
    } catch (const InputError&) {
      // A damaged picture leaves its cell white; the page shows the same file as broken.
    }
  }
  std::error_code ec;
  if (tiles.empty()) {
    fs::remove(target, ec);
    return false;
  }
  std::vector<int> widths(std::size_t(std::max(figure.columns, 1)), 0);
  std::vector<int> heights(std::size_t(rows), 0);
  for (const Tile& tile : tiles) {
    int& width = widths[std::size_t(tile.column)];
    int& height = heights[std::size_t(tile.row)];
    width = std::max(width, tile.picture.width);
    height = std::max(height, tile.picture.height);
  }
  const std::vector<int> xs = offsets(widths), ys = offsets(heights);
  image::DisplayPicture composite(total(widths), total(heights), 255);
  for (const Tile& tile : tiles) {
    const int x0 =
        xs[std::size_t(tile.column)] + (widths[std::size_t(tile.column)] - tile.picture.width) / 2;
    const int y0 =
        ys[std::size_t(tile.row)] + (heights[std::size_t(tile.row)] - tile.picture.height) / 2;
    for (int y = 0; y < tile.picture.height; ++y)
      std::copy_n(tile.picture.pixel(0, y), std::size_t(tile.picture.width) * 3,
                  composite.pixel(x0, y0 + y));
  }
  fs::create_directories(target.parent_path(), ec);
  image::writeDisplayPng(target, composite);
  return true;
}

}  // namespace gib::reports
