#include "reports/html_report.h"

#include "common/input_error.h"
#include "image/output_files.h"
#include "reports/figure_files.h"
#include "reports/figure_page.h"
#include "reports/figure_panels.h"
#include "reports/index_page.h"
#include "reports/job_page.h"
#include "reports/report_labels.h"
#include "reports/run_comparison.h"

#include <fmt/format.h>

#include <set>

namespace gib::reports {

namespace {

namespace fs = std::filesystem;

// Slugs become file names under report/: a hand-edited results.json must not write elsewhere or
// let two jobs share a page.
void checkSlugs(const results::RunResults& results) {
  std::set<std::string> seen;
  for (const results::JobResult& job : results.jobs) {
    const std::string& slug = job.slug;
    if (slug.empty() || slug == "." || slug == ".." ||
        slug.find_first_of(std::string("/\\\0", 3)) != std::string::npos)
      throw InputError(fmt::format(
          "job '{}' has the slug '{}', which is not a file name; fix the job's \"slug\" in "
          "results.json or run the suite again",
          job.id, slug));
    if (!seen.insert(slug).second)
      throw InputError(fmt::format(
          "two jobs have the slug '{}' (the second is '{}'); give each job its own slug in "
          "results.json or run the suite again",
          slug, job.id));
  }
}

}  // namespace

fs::path writeHtmlReport(const fs::path& run_dir, const results::RunResults& results,
                         const ReportContext& context) {
  checkSlugs(results);
  checkFigureNames(results);
  std::error_code ec;
  if (!fs::is_directory(run_dir, ec))
    throw InputError(
        fmt::format("run directory '{}' does not exist; give the directory "
                    "`gibench run --out` wrote",
                    run_dir.string()));
  fs::create_directories(run_dir / "report", ec);
  if (!fs::is_directory(run_dir / "report", ec))
    throw InputError(fmt::format("cannot create '{}'; make the run directory writable",
                                 (run_dir / "report").string()));

  const RunComparison comparison(results, context.previous, context.history);
  // Job pages first: index.html never links to a page that is not there yet.
  for (const results::JobResult& job : results.jobs)
    image::writeTextFile(run_dir / jobPageFile(job),
                         jobPage(run_dir, results, job, comparison, context));
  // The standalone figures before the figure pages that link them.
  writeFigureFiles(run_dir, results);
  for (const results::FigureSpec& figure : results.figures)
    image::writeTextFile(run_dir / figurePageFile(figure), figurePage(run_dir, results, figure));
  const fs::path index = run_dir / "index.html";
  image::writeTextFile(index, indexPage(run_dir, results, comparison));
  return index;
}

}  // namespace gib::reports
