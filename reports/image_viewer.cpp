#include "reports/image_viewer.h"

#include "reports/html_text.h"
#include "reports/report_labels.h"
#include "reports/svg_charts.h"

#include <fmt/format.h>

#include <algorithm>
#include <vector>

namespace gib::reports {

namespace {

namespace fs = std::filesystem;

// Pictures narrower than this are enlarged by a whole factor (pixelated, so pixels stay pixels).
constexpr int kViewerWidth = 512;

struct Layer {
  const char* name;    // data-layer: the script's handle
  const char* button;  // button text
  std::string alt;     // what the picture shows
  const std::string* path;
};

bool exists(const fs::path& run_dir, const std::string& path) {
  std::error_code ec;
  return fs::is_regular_file(fs::path(path).is_absolute() ? fs::path(path) : run_dir / path, ec);
}

}  // namespace

std::string imageViewer(const fs::path& run_dir, const results::JobResult& job) {
  const results::JobOutputs& out = job.outputs;
  const bool is_reference = job.technique == "reference";
  const std::vector<Layer> candidates = {
      {"reference", "Reference", fmt::format("Reference ({})", job.reference.path_class),
       &out.reference_png},
      {"image", is_reference ? "Test render" : "Image",
       is_reference ? "Test render of the reference renderer" : "Image of " + job.technique,
       &out.image_png},
      {"difference", "Difference", "Difference from the reference, amplified", &out.difference_png},
      {"flip", "FLIP", "FLIP error map (magma colour map, scale below)", &out.flip_png},
  };
  std::vector<Layer> layers;
  std::vector<std::string> absent;
  for (const Layer& layer : candidates) {
    if (layer.path->empty()) continue;
    if (exists(run_dir, *layer.path))
      layers.push_back(layer);
    else
      absent.push_back(*layer.path);
  }
  std::string notes;
  if (!absent.empty()) {
    std::string list;
    for (const std::string& path : absent) list += (list.empty() ? "" : ", ") + escapeHtml(path);
    notes = fmt::format(
        "<p class=\"note\">Listed in the results but absent when the report was written: {}.</p>\n",
        list);
  }
  if (layers.empty())
    return notes + "<p class=\"note\">No pictures were written for this job.</p>\n";

  const auto has = [&](const char* name) {
    return std::any_of(layers.begin(), layers.end(),
                       [&](const Layer& l) { return std::string_view(l.name) == name; });
  };
  const char* shown = has("image") ? "image" : layers.front().name;
  const int scale = job.width > 0 ? std::max(1, kViewerWidth / job.width) : 1;
  const std::string size =
      job.width > 0 && job.height > 0
          ? fmt::format(" width=\"{}\" height=\"{}\"", job.width * scale, job.height * scale)
          : std::string();
  std::string buttons, images;
  for (const Layer& layer : layers) {
    buttons += fmt::format("<button type=\"button\" data-layer=\"{}\">{}</button>", layer.name,
                           layer.button);
    images += fmt::format("<img class=\"layer\" data-layer=\"{}\" src=\"{}\" alt=\"{}\"{}{}>",
                          layer.name, escapeHtml(outputHref(*layer.path, 1)), escapeHtml(layer.alt),
                          size, std::string_view(layer.name) == shown ? "" : " hidden");
  }
  std::string html = fmt::format(
      "<div class=\"viewer\" data-show=\"{}\">\n<div>{}</div>\n"
      "<div class=\"viewer-stage\">{}</div>\n<p class=\"viewer-caption muted\"></p>\n</div>\n",
      shown, buttons, images);
  if (has("reference") && has("image"))
    html +=
        "<p class=\"muted\">Hover over the picture to swap between the reference and the "
        "image.</p>\n";
  if (has("flip")) html += flipColorBar() + "\n";
  return html + notes;
}

std::string auxiliaryImages(const fs::path& run_dir, const results::JobResult& job) {
  std::string figures, absent;
  for (const results::AuxiliaryImageOutput& aux : job.auxiliary_images) {
    if (!exists(run_dir, aux.png)) {
      absent += (absent.empty() ? "" : ", ") + escapeHtml(aux.png);
      continue;
    }
    figures += fmt::format(
        "<figure class=\"auxiliary\"><img src=\"{}\" alt=\"{}\"><figcaption>{}: {}"
        "</figcaption></figure>\n",
        escapeHtml(outputHref(aux.png, 1)), escapeHtml(aux.name), escapeHtml(aux.name),
        escapeHtml(aux.description));
  }
  if (figures.empty() && absent.empty()) return {};
  std::string html = "<div class=\"charts\">\n" + figures + "</div>\n";
  if (!absent.empty())
    html += fmt::format(
        "<p class=\"note\">Listed in the results but absent when the report was written: {}."
        "</p>\n",
        absent);
  return html;
}

}  // namespace gib::reports
