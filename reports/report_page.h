// The frame every report page shares: one HTML document with its style sheet and scripts
// inline (the report opens from disk with no network), the warning banner of the self-check, and
// the tables the pages are made of.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace gib::reports {

// A whole document. `body` is HTML. The page carries the image viewer's script (viewer.js, which
// drives the job pages' viewers) and a self-check that, when the window has loaded, checks that
// every <img> decoded (complete, naturalWidth > 0), every image viewer is ready with the viewer
// data it names, and every chart <svg> has a non-empty bounding box, and records the outcome as
// data-report-check="ok" or "failed: <what>" on <html>; on failure it also shows a banner naming
// what is missing (a report copied without its images).
std::string htmlPage(std::string_view title, std::string_view body);

// <section> with an <h2> heading (escaped) and `body` (HTML).
std::string htmlSection(std::string_view id, std::string_view heading, std::string_view body);

// A line naming the GL renderer (GL_RENDERER) the page's timings come from, with `scope` in
// brackets when not empty ("the run's technique jobs"); a software rasteriser
// (isSoftwareRasteriser: llvmpipe, softpipe, swrast) is flagged as not representative of GPU
// timings. Every page of a run's report carries one.
std::string rendererNote(std::string_view renderer, std::string_view scope = {});

struct TableColumn {
  std::string heading;   // text (escaped)
  bool numeric = false;  // right-aligned, tabular figures
};

// A table whose cells are HTML the caller escaped (escapeHtml for text).
class HtmlTable {
 public:
  explicit HtmlTable(std::vector<TableColumn> columns, std::string_view css_class = {});
  // One cell per column; `row_class` sets the row's class when not empty.
  void addRow(const std::vector<std::string>& cells, std::string_view row_class = {});
  bool empty() const { return rows_.empty(); }
  std::string html() const;

 private:
  std::vector<TableColumn> columns_;
  std::string css_class_;
  std::string rows_;
};

// Two columns, name and value, of plain text (both escaped here); rows with an empty value are
// left out.
std::string factsTable(const std::vector<std::pair<std::string, std::string>>& facts);

}  // namespace gib::reports
