// A figure's panels in one picture (figures/<name>.png), for a paper or a pull request: composited
// from the PNGs the report shows, byte for byte, since they are display-referred already (a second
// display transform would change them).
#pragma once

#include "results/results.h"

#include <filesystem>

namespace gib::reports {

// White between neighbouring cells, in pixels.
inline constexpr int kFigureGapPixels = 4;

// Writes the panels of `figure` into `target` in the figure's grid: each column as wide as its
// widest picture, each row as tall as its tallest, kFigureGapPixels of white between columns and
// between rows (none around the edge), each picture centred in its cell (rounded towards the top
// left). A cell whose picture is absent or unreadable stays white, and so has no size of its own.
// Returns false, and removes an older `target`, when no panel has a picture.
bool writeFigurePng(const std::filesystem::path& run_dir, const results::RunResults& results,
                    const results::FigureSpec& figure, const std::filesystem::path& target);

}  // namespace gib::reports
