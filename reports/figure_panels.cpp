#include "reports/figure_panels.h"

#include "common/input_error.h"
#include "common/join.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <set>
#include <string_view>

namespace gib::reports {

namespace {

namespace fs = std::filesystem;

constexpr std::string_view kAuxiliaryPrefix = "aux:";

bool isFileName(std::string_view name) {
  return !name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_';
  });
}

// The listed PNG of the panel's output; empty with `absent` set when the job has none.
std::string listedPicture(const results::JobResult& job, const std::string& image,
                          std::string& absent) {
  const results::JobOutputs& out = job.outputs;
  if (image.starts_with(kAuxiliaryPrefix)) {
    const std::string name = image.substr(kAuxiliaryPrefix.size());
    for (const results::AuxiliaryImageOutput& aux : job.auxiliary_images)
      if (aux.name == name && !aux.png.empty()) return aux.png;
    const std::string known =
        joinNames(job.auxiliary_images, ", ", [](const auto& aux) { return aux.name; });
    absent = fmt::format("job '{}' has no auxiliary image '{}' ({})", job.id, name,
                         known.empty() ? "it has none" : "it has " + known);
    return {};
  }
  const std::string* path = image == "reference"    ? &out.reference_png
                            : image == "difference" ? &out.difference_png
                            : image == "flip"       ? &out.flip_png
                                                    : &out.image_png;
  if (path->empty()) absent = fmt::format("job '{}' wrote no {} picture", job.id, image);
  return *path;
}

}  // namespace

PanelPicture panelPicture(const fs::path& run_dir, const results::RunResults& results,
                          const results::FigureSpec::Panel& panel) {
  PanelPicture picture;
  picture.job = results.findJob(panel.job);
  if (!picture.job) {
    picture.absent = fmt::format("job '{}' is not in this run", panel.job);
    return picture;
  }
  if (picture.job->failed()) {
    picture.absent = fmt::format("job '{}' failed", panel.job);
    return picture;
  }
  const std::string listed = listedPicture(*picture.job, panel.image, picture.absent);
  if (listed.empty()) return picture;
  std::error_code ec;
  if (!fs::is_regular_file(fs::path(listed).is_absolute() ? fs::path(listed) : run_dir / listed,
                           ec)) {
    picture.absent = fmt::format(
        "{} is listed in the results but was absent when the report was written", listed);
    return picture;
  }
  picture.path = listed;
  return picture;
}

std::vector<std::string> figureJobs(const results::FigureSpec& figure) {
  std::vector<std::string> jobs;
  for (const results::FigureSpec::Panel& panel : figure.panels)
    if (std::find(jobs.begin(), jobs.end(), panel.job) == jobs.end()) jobs.push_back(panel.job);
  return jobs;
}

std::string figurePageFile(const results::FigureSpec& figure) {
  return "report/figure-" + figure.name + ".html";
}

std::string figurePngFile(const results::FigureSpec& figure) {
  return "figures/" + figure.name + ".png";
}

void checkFigureNames(const results::RunResults& results) {
  std::set<std::string> seen;
  for (const results::FigureSpec& figure : results.figures) {
    if (!isFileName(figure.name))
      throw InputError(fmt::format(
          "figure '{}' has a name that is not a file name (letters, digits, '-', '_'); fix the "
          "figure's \"name\" in results.json or run the suite again",
          figure.name));
    if (!seen.insert(figure.name).second)
      throw InputError(fmt::format(
          "two figures are named '{}'; give each figure its own name in results.json or run the "
          "suite again",
          figure.name));
    for (const results::JobResult& job : results.jobs)
      if (job.slug == "figure-" + figure.name)
        throw InputError(fmt::format(
            "figure '{}' would have the page of job '{}' ({}); rename the figure in results.json "
            "or run the suite again",
            figure.name, job.id, figurePageFile(figure)));
  }
}

}  // namespace gib::reports
