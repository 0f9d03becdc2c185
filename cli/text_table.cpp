#include "cli/text_table.h"

#include <algorithm>
#include <stdexcept>

namespace gib::cli {

namespace {

// Display width: UTF-8 continuation bytes take no column (renderer names may hold "®").
std::size_t displayWidth(const std::string& text) {
  return std::size_t(std::count_if(text.begin(), text.end(), [](char c) {
    return (static_cast<unsigned char>(c) & 0xC0) != 0x80;
  }));
}

}  // namespace

std::string formatTable(const std::vector<std::string>& header,
                        const std::vector<std::vector<std::string>>& rows) {
  std::vector<std::size_t> widths(header.size());
  auto measure = [&](const std::vector<std::string>& row) {
    if (row.size() != header.size())
      throw std::logic_error("formatTable: a row and the header differ in length");
    for (std::size_t i = 0; i < row.size(); ++i)
      widths[i] = std::max(widths[i], displayWidth(row[i]));
  };
  measure(header);
  for (const auto& row : rows) measure(row);

  std::string out;
  auto append = [&](const std::vector<std::string>& row) {
    for (std::size_t i = 0; i < row.size(); ++i) {
      out += row[i];
      if (i + 1 < row.size()) out += std::string(widths[i] - displayWidth(row[i]) + 2, ' ');
    }
    out += '\n';
  };
  append(header);
  for (const auto& row : rows) append(row);
  return out;
}

}  // namespace gib::cli
