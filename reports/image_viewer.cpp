#include "reports/image_viewer.h"

#include "image/false_color.h"
#include "reports/html_text.h"
#include "reports/report_labels.h"
#include "reports/svg_charts.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace gib::reports {

namespace {

namespace fs = std::filesystem;

struct Layer {
  const char* name;        // the viewer's handle (viewer.js)
  const char* label;       // what the layer menus call it
  std::string alt;         // what the picture shows
  const std::string* png;  // its PNG: the fallback of a run without linear data; null for a layer
                           // that exists only as linear data
  bool linear = false;     // in the viewer data, or made by the viewer from it
};

bool exists(const fs::path& run_dir, const std::string& path) {
  std::error_code ec;
  return fs::is_regular_file(fs::path(path).is_absolute() ? fs::path(path) : run_dir / path, ec);
}

// The magma colour map as 256 sRGB triples in hex, for the viewer's false colour and FLIP layer:
// the same map the PNGs use (image/false_color.h), so the two never disagree.
std::string magmaHex() {
  std::string hex;
  for (int i = 0; i < 256; ++i) {
    float rgb[3];
    image::magmaSrgb(float(i) / 255.0f, rgb);
    for (float c : rgb)
      hex += fmt::format("{:02x}", int(std::lround(std::clamp(c, 0.0f, 1.0f) * 255)));
  }
  return hex;
}

std::string selectMenu(const char* role, const char* label, const std::vector<Layer>& layers,
                       const char* chosen) {
  std::string options;
  for (const Layer& layer : layers)
    options += fmt::format("<option value=\"{}\"{}>{}</option>", layer.name,
                           std::string_view(layer.name) == chosen ? " selected" : "", layer.label);
  return fmt::format("<label>{} <select data-role=\"{}\">{}</select></label>", label, role,
                     options);
}

}  // namespace

std::string imageViewer(const fs::path& run_dir, const results::JobResult& job) {
  const results::JobOutputs& out = job.outputs;
  const bool is_reference = job.technique == "reference";
  const bool job_data = !out.viewer_data.empty() && exists(run_dir, out.viewer_data);
  const bool reference_data =
      !out.reference_viewer_data.empty() && exists(run_dir, out.reference_viewer_data);
  const bool linear = job_data && reference_data;
  const bool has_image = !out.image_png.empty() && exists(run_dir, out.image_png);
  // The viewer makes the signed and relative errors from the image and the reference.
  const bool errors = linear && has_image;
  const std::vector<Layer> candidates = {
      {"reference", "Reference", fmt::format("Reference ({})", job.reference.path_class),
       &out.reference_png, reference_data},
      {"image", is_reference ? "Test render" : "Image",
       is_reference ? "Test render of the reference renderer" : "Image of " + job.technique,
       &out.image_png, job_data && has_image},
      {"difference", "Difference", "Difference from the reference", &out.difference_png, errors},
      {"signed", "Signed difference", "", nullptr, errors},
      {"relative", "Relative error", "", nullptr, errors},
      {"flip", "FLIP", "FLIP error map (magma colour map, scale below)", &out.flip_png,
       job_data && !out.flip_png.empty()},
      {"stderr", "Standard error", "", nullptr, reference_data},
  };
  std::vector<Layer> layers;
  std::vector<std::string> absent;
  std::string pngs;
  for (const Layer& layer : candidates) {
    const bool png = layer.png && !layer.png->empty();
    if (png && !exists(run_dir, *layer.png)) {
      absent.push_back(*layer.png);
      continue;
    }
    if (png)
      pngs += fmt::format("<img class=\"layer\" data-layer=\"{}\" src=\"{}\" alt=\"{}\">",
                          layer.name, escapeHtml(outputHref(*layer.png, 1)), escapeHtml(layer.alt));
    // A layer without a PNG is offered only with its linear data (a reference of one replica
    // has no standard error).
    if (png || (!layer.png && layer.linear)) layers.push_back(layer);
  }
  std::string notes;
  if (!absent.empty()) {
    std::string list;
    for (const std::string& path : absent) list += (list.empty() ? "" : ", ") + escapeHtml(path);
    notes = fmt::format(
        "<p class=\"note\">Listed in the results but absent when the report was written: {}.</p>\n",
        list);
  }
  if (layers.empty() || job.width <= 0 || job.height <= 0)
    return notes + "<p class=\"note\">No pictures were written for this job.</p>\n";

  const auto has = [&](const char* name) {
    return std::any_of(layers.begin(), layers.end(),
                       [&](const Layer& l) { return std::string_view(l.name) == name; });
  };
  const char* a = has("reference") ? "reference" : layers.front().name;
  const char* b = has("image") ? "image" : has("stderr") ? "stderr" : layers.back().name;
  std::string data_attributes, scripts;
  if (linear) {
    data_attributes =
        fmt::format(" data-job-data=\"{}\" data-reference-data=\"{}\"", escapeHtml(out.viewer_data),
                    escapeHtml(out.reference_viewer_data));
    for (const std::string* path : {&out.reference_viewer_data, &out.viewer_data})
      scripts += fmt::format("<script src=\"{}\"></script>\n", escapeHtml(outputHref(*path, 1)));
  }
  // Each pane in a box with its full-window button; the colour bars and the readout are filled
  // in by viewer.js.
  const auto pane = [](const char* id) {
    return fmt::format(
        "<div class=\"viewer-pane\" data-pane-box=\"{0}\"><canvas data-pane=\"{0}\"></canvas>"
        "<button type=\"button\" class=\"viewer-full-button\" data-full=\"{0}\" "
        "aria-pressed=\"false\" title=\"Fill the window with this pane (Esc: back)\">Full "
        "window</button></div>",
        id);
  };
  std::string html = fmt::format(
      "<div class=\"viewer\" data-width=\"{}\" data-height=\"{}\" data-a=\"{}\" data-b=\"{}\"{} "
      "data-magma=\"{}\">\n<div class=\"viewer-tools\">{} {} <span class=\"viewer-modes\">"
      "<button type=\"button\" data-mode=\"side\">Side by side</button><button type=\"button\" "
      "data-mode=\"wipe\">Wipe</button></span> <label>Exposure <input type=\"range\" "
      "data-role=\"exposure\" min=\"-10\" max=\"10\" step=\"0.5\" value=\"0\"> <output "
      "data-role=\"exposure-value\">+0 EV</output></label> <label><input type=\"checkbox\" "
      "data-role=\"false-colour\"> False colour</label> <label title=\"Error layers: the colour "
      "map spans the layer's values (to their 99th percentile); off: it spans 2^-exposure (FLIP: "
      "0 to 1)\"><input type=\"checkbox\" data-role=\"auto-range\" checked> Auto range</label> "
      "<span class=\"viewer-zoom\">Zoom <button type=\"button\" data-zoom=\"out\">−</button>"
      "<output data-role=\"zoom\"></output><button type=\"button\" data-zoom=\"in\">+</button>"
      "<button type=\"button\" data-zoom=\"fit\">Fit</button></span></div>\n<div "
      "class=\"viewer-stage\">{}{}</div>\n<input type=\"range\" data-role=\"wipe\" "
      "class=\"viewer-wipe\" min=\"0\" max=\"1\" step=\"0.001\" value=\"0.5\" "
      "aria-label=\"wipe position\" hidden>\n<div class=\"viewer-scales\"><div "
      "class=\"viewer-scale\" data-scale=\"a\" hidden></div><div class=\"viewer-scale\" "
      "data-scale=\"b\" hidden></div></div>\n<div class=\"viewer-readout\" "
      "data-role=\"readout\">Point at a pixel for its values; click to pin it.</div>\n<div "
      "class=\"viewer-sources\" hidden>{}</div>\n</div>\n{}",
      job.width, job.height, a, b, data_attributes, magmaHex(), selectMenu("a", "Left", layers, a),
      selectMenu("b", "Right", layers, b), pane("a"), pane("b"), pngs, scripts);
  html += linear ? "<p class=\"muted\">Wheel: zoom about the pointer, in proportion to the "
                   "wheel's turn · drag: pan (in wipe mode, drag the line to move it) · exposure "
                   "and false colour act on the linear values; error layers show their values "
                   "through a colour map with its bar (signed difference: blue where the image is "
                   "darker than the reference, red where brighter) · Full window: one pane fills "
                   "the window (Esc returns) · the view is kept in the address, to link to.</p>\n"
                 : "<p class=\"note\">This run has no linear viewer data (written before the "
                   "viewer had it): the pictures are its PNGs, without exposure or values.</p>\n";
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
