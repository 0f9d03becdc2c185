#include "reports/svg_writer.h"

#include "reports/html_text.h"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace gib::reports {

SvgWriter::SvgWriter(double width, double height, std::string_view label) {
  body_ = fmt::format(
      R"(<svg class="chart" xmlns="http://www.w3.org/2000/svg" viewBox="0 0 {0} {1}" )"
      R"(width="{0}" height="{1}" role="img" aria-label="{2}" font-family="sans-serif" )"
      R"(font-size="11"><title>{2}</title>)",
      number(width), number(height), escapeHtml(label));
}

std::string SvgWriter::number(double value) {
  if (!std::isfinite(value)) throw std::logic_error("a chart computed a non-finite coordinate");
  std::string text = fmt::format("{:.1f}", value);
  if (text == "-0.0") text = "0.0";
  return text;
}

std::string SvgWriter::moveTo(double x, double y) {
  return fmt::format("M{} {}", number(x), number(y));
}
std::string SvgWriter::horizontalTo(double x) {
  return fmt::format("H{}", number(x));
}
std::string SvgWriter::verticalTo(double y) {
  return fmt::format("V{}", number(y));
}

void SvgWriter::shape(std::string_view element, const std::string& geometry,
                      std::string_view attributes, std::string_view tooltip) {
  body_ += fmt::format("<{} {}", element, geometry);
  if (!attributes.empty()) body_ += fmt::format(" {}", attributes);
  if (tooltip.empty())
    body_ += "/>";
  else
    body_ += fmt::format("><title>{}</title></{}>", escapeHtml(tooltip), element);
}

void SvgWriter::rect(double x, double y, double width, double height, std::string_view attributes,
                     std::string_view tooltip) {
  shape("rect",
        fmt::format(R"(x="{}" y="{}" width="{}" height="{}")", number(x), number(y), number(width),
                    number(height)),
        attributes, tooltip);
}

void SvgWriter::line(double x1, double y1, double x2, double y2, std::string_view attributes) {
  shape("line",
        fmt::format(R"(x1="{}" y1="{}" x2="{}" y2="{}")", number(x1), number(y1), number(x2),
                    number(y2)),
        attributes, {});
}

void SvgWriter::circle(double cx, double cy, double r, std::string_view attributes,
                       std::string_view tooltip) {
  shape("circle", fmt::format(R"(cx="{}" cy="{}" r="{}")", number(cx), number(cy), number(r)),
        attributes, tooltip);
}

void SvgWriter::polyline(const std::vector<std::pair<double, double>>& points,
                         std::string_view attributes) {
  std::string list;
  for (const auto& [x, y] : points) {
    if (!list.empty()) list += ' ';
    list += number(x) + "," + number(y);
  }
  shape("polyline", fmt::format(R"(points="{}" fill="none")", list), attributes, {});
}

void SvgWriter::path(std::string_view data, std::string_view attributes) {
  shape("path", fmt::format(R"(d="{}")", data), attributes, {});
}

void SvgWriter::text(double x, double y, std::string_view content, std::string_view anchor,
                     std::string_view attributes, double degrees) {
  body_ += fmt::format(R"(<text x="{}" y="{}" text-anchor="{}")", number(x), number(y), anchor);
  if (degrees != 0)
    body_ += fmt::format(R"svg( transform="rotate({} {} {})")svg", number(degrees), number(x),
                         number(y));
  if (!attributes.empty()) body_ += fmt::format(" {}", attributes);
  body_ += fmt::format(">{}</text>", escapeHtml(content));
}

}  // namespace gib::reports
