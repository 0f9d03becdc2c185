// A small writer of inline SVG for the report's charts: a root element with a viewBox, the
// shapes the charts use, and text that is always escaped. Coordinates are written with one
// decimal; a non-finite coordinate is a bug in the chart that computed it and throws
// std::logic_error rather than writing "nan" into a page.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace gib::reports {

class SvgWriter {
 public:
  // The root element: class "chart" (the page's self-check looks for it), a viewBox of the
  // given size in pixels, role="img" with `label` as its accessible name and <title>.
  SvgWriter(double width, double height, std::string_view label);

  // `attributes` are further attributes written as given ("fill=\"#36c\""), so a chart keeps
  // its look without the page's style sheet. `tooltip` becomes a <title> child when not empty.
  void rect(double x, double y, double width, double height, std::string_view attributes,
            std::string_view tooltip = {});
  void line(double x1, double y1, double x2, double y2, std::string_view attributes);
  void circle(double cx, double cy, double r, std::string_view attributes,
              std::string_view tooltip = {});
  void polyline(const std::vector<std::pair<double, double>>& points, std::string_view attributes);
  // Path data built with moveTo/horizontalTo/verticalTo below.
  void path(std::string_view data, std::string_view attributes);
  // Text at (x, y) with the given anchor ("start", "middle", "end"), rotated by `degrees` about
  // its anchor point.
  void text(double x, double y, std::string_view content, std::string_view anchor = "start",
            std::string_view attributes = {}, double degrees = 0);
  // Markup the caller built from this writer's pieces (a gradient definition).
  void raw(std::string_view markup) { body_ += markup; }

  std::string finish() const { return body_ + "</svg>"; }

  // One coordinate as written ("12.5"); throws std::logic_error when not finite.
  static std::string number(double value);
  static std::string moveTo(double x, double y);
  static std::string horizontalTo(double x);
  static std::string verticalTo(double y);

 private:
  void shape(std::string_view element, const std::string& geometry, std::string_view attributes,
             std::string_view tooltip);
  std::string body_;
};

}  // namespace gib::reports
