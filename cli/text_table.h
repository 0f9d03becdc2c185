// Tables for people on stdout: left-aligned columns two spaces apart, a header row first.
#pragma once

#include <string>
#include <vector>

namespace gib::cli {

// Each row has the header's number of cells; the last column is not padded (no trailing blanks).
std::string formatTable(const std::vector<std::string>& header,
                        const std::vector<std::vector<std::string>>& rows);

}  // namespace gib::cli
