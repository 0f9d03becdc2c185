#include "reports/report_page.h"

#include "reports/html_text.h"

#include <fmt/format.h>

#include <stdexcept>

namespace gib::reports {

namespace {

constexpr const char* kStyle = R"css(
body { font: 14px/1.45 system-ui, sans-serif; margin: 1.5em auto; max-width: 1200px; padding: 0 1em; color: #1d1d1d; }
h1 { font-size: 1.5em; margin-bottom: 0.2em; } h2 { font-size: 1.2em; margin-top: 1.8em; border-bottom: 1px solid #ccc; }
table { border-collapse: collapse; margin: 0.5em 0; } th, td { padding: 0.2em 0.7em; border-bottom: 1px solid #e4e4e4; text-align: left; vertical-align: top; }
th { background: #f3f3f3; } td.num, th.num { text-align: right; font-variant-numeric: tabular-nums; }
.facts th { background: none; font-weight: 600; color: #444; }
.matrix td { min-width: 12em; } .matrix .job { border-left: 4px solid #bbb; padding: 0.2em 0.5em; margin: 0.2em 0; }
.verdict-regressed { background: #fbe0dd; border-color: #c0392b !important; color: #7d1d12; }
.verdict-improved { background: #ddf3df; border-color: #2e8b40 !important; color: #1d5c29; }
.verdict-unchanged { background: #f5f5f5; }
.legend span { display: inline-block; padding: 0.1em 0.6em; margin-right: 0.5em; border-left: 4px solid #bbb; }
.muted { color: #666; } .note { color: #666; font-style: italic; }
#report-check { background: #c0392b; color: #fff; padding: 0.6em 1em; font-weight: 600; }
.viewer-stage { display: inline-block; cursor: crosshair; } .viewer-stage img { display: block; image-rendering: pixelated; max-width: 100%; height: auto; }
.viewer-stage img[hidden] { display: none; }
.viewer button { font: inherit; margin: 0 0.3em 0.4em 0; padding: 0.2em 0.8em; border: 1px solid #888; background: #fafafa; cursor: pointer; }
.viewer button[aria-pressed="true"] { background: #2f5f98; color: #fff; border-color: #2f5f98; }
.charts { display: flex; flex-wrap: wrap; gap: 1em; align-items: flex-start; } svg.chart { max-width: 100%; height: auto; }
)css";

// Self-check and image viewer; plain ES5 so any browser of the last decade runs it.
constexpr const char* kScript = R"js(
(function () {
  function each(list, f) { Array.prototype.forEach.call(list, f); }
  each(document.querySelectorAll('.viewer'), function (viewer) {
    var chosen = viewer.getAttribute('data-show');
    var partner = { image: 'reference', reference: 'image' };
    function layer(name) { return viewer.querySelector('.layer[data-layer="' + name + '"]'); }
    function show(name) {
      each(viewer.querySelectorAll('.layer'), function (l) { l.hidden = l.getAttribute('data-layer') !== name; });
      each(viewer.querySelectorAll('button[data-layer]'), function (b) {
        b.setAttribute('aria-pressed', String(b.getAttribute('data-layer') === chosen));
      });
      var caption = viewer.querySelector('.viewer-caption');
      if (caption && layer(name)) caption.textContent = layer(name).alt + (name === chosen ? '' : ' (while the pointer is on the image)');
    }
    each(viewer.querySelectorAll('button[data-layer]'), function (b) {
      b.addEventListener('click', function () { chosen = b.getAttribute('data-layer'); show(chosen); });
    });
    var stage = viewer.querySelector('.viewer-stage');
    stage.addEventListener('mouseenter', function () { if (layer(partner[chosen])) show(partner[chosen]); });
    stage.addEventListener('mouseleave', function () { show(chosen); });
    show(chosen);
  });
  window.addEventListener('load', function () {
    var problems = [];
    each(document.images, function (img) {
      if (!img.complete || img.naturalWidth === 0) problems.push('image ' + img.getAttribute('src'));
    });
    each(document.querySelectorAll('.viewer'), function (viewer, i) {
      var shown = 0;
      each(viewer.querySelectorAll('.layer'), function (l) { if (l.offsetParent !== null) shown += 1; });
      if (shown !== 1) problems.push('image viewer ' + (i + 1) + ' shows ' + shown + ' pictures instead of one');
    });
    each(document.querySelectorAll('svg.chart'), function (svg) {
      var box = svg.getBBox(), rect = svg.getBoundingClientRect();
      if (!(box.width > 0 && box.height > 0 && rect.width > 0 && rect.height > 0))
        problems.push('chart "' + svg.getAttribute('aria-label') + '"');
    });
    var root = document.documentElement;
    if (problems.length === 0) { root.setAttribute('data-report-check', 'ok'); return; }
    root.setAttribute('data-report-check', 'failed: ' + problems.join('; '));
    var banner = document.getElementById('report-check');
    banner.textContent = 'This page is incomplete: ' + problems.join('; ') +
        ' did not render. Keep the whole run directory (jobs/, report/ and index.html) together.';
    banner.hidden = false;
  });
})();
)js";

}  // namespace

std::string htmlPage(std::string_view title, std::string_view body) {
  // The empty icon link stops the browser asking the disk for a favicon.ico that is not there.
  return fmt::format(
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
      "<title>{}</title>\n<link rel=\"icon\" href=\"data:,\">\n<style>{}</style>\n</head>\n"
      "<body>\n<div id=\"report-check\" role=\"alert\" hidden></div>\n{}\n<script>{}</script>\n"
      "</body>\n</html>\n",
      escapeHtml(title), kStyle, body, kScript);
}

std::string htmlSection(std::string_view id, std::string_view heading, std::string_view body) {
  return fmt::format("<section id=\"{}\">\n<h2>{}</h2>\n{}\n</section>\n", escapeHtml(id),
                     escapeHtml(heading), body);
}

HtmlTable::HtmlTable(std::vector<TableColumn> columns, std::string_view css_class)
    : columns_(std::move(columns)), css_class_(css_class) {}

void HtmlTable::addRow(const std::vector<std::string>& cells, std::string_view row_class) {
  if (cells.size() != columns_.size())
    throw std::logic_error(
        fmt::format("a table row of {} cells for {} columns", cells.size(), columns_.size()));
  rows_ += row_class.empty() ? "<tr>" : fmt::format("<tr class=\"{}\">", escapeHtml(row_class));
  for (std::size_t i = 0; i < cells.size(); ++i)
    rows_ += fmt::format("<td{}>{}</td>", columns_[i].numeric ? " class=\"num\"" : "", cells[i]);
  rows_ += "</tr>\n";
}

std::string HtmlTable::html() const {
  std::string head;
  for (const TableColumn& column : columns_)
    head += fmt::format("<th{}>{}</th>", column.numeric ? " class=\"num\"" : "",
                        escapeHtml(column.heading));
  return fmt::format("<table{}>\n<thead><tr>{}</tr></thead>\n<tbody>\n{}</tbody>\n</table>\n",
                     css_class_.empty() ? "" : fmt::format(" class=\"{}\"", escapeHtml(css_class_)),
                     head, rows_);
}

std::string factsTable(const std::vector<std::pair<std::string, std::string>>& facts) {
  std::string rows;
  for (const auto& [name, value] : facts)
    if (!value.empty())
      rows += fmt::format("<tr><th scope=\"row\">{}</th><td>{}</td></tr>\n", escapeHtml(name),
                          escapeHtml(value));
  return fmt::format("<table class=\"facts\">\n<tbody>\n{}</tbody>\n</table>\n", rows);
}

}  // namespace gib::reports
