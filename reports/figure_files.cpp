#include "reports/figure_files.h"

#include "common/input_error.h"
#include "image/output_files.h"
#include "reports/figure_charts.h"
#include "reports/figure_composite.h"
#include "reports/figure_panels.h"

#include <fmt/format.h>

namespace gib::reports {

namespace fs = std::filesystem;

void writeFigureFiles(const fs::path& run_dir, const results::RunResults& results) {
  if (results.charts.empty() && results.figures.empty()) return;
  std::error_code ec;
  fs::create_directories(run_dir / "figures", ec);
  if (!fs::is_directory(run_dir / "figures", ec))
    throw InputError(fmt::format("cannot create '{}'; make the run directory writable",
                                 (run_dir / "figures").string()));
  for (std::size_t i = 0; i < results.charts.size(); ++i)
    image::writeTextFile(run_dir / chartSvgFile(results, i),
                         standaloneChartSvg(results, results.charts[i]));
  for (const results::FigureSpec& figure : results.figures)
    writeFigurePng(run_dir, results, figure, run_dir / figurePngFile(figure));
}

}  // namespace gib::reports
