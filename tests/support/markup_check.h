// A well-formedness check of generated HTML and SVG for the report tests: every element that is
// opened is closed, in order. Not a parser: enough to catch a missing </tr> or a stray </svg>.
#pragma once

#include <string>
#include <string_view>

namespace gib::test {

// "" when balanced; otherwise what is wrong ("</div> closes <span>", "<table> never closed").
// HTML void elements (meta, link, img, br, hr, input) and self-closed tags ("<rect/>") need no
// end tag; comments, the doctype and the contents of <script> and <style> are skipped.
std::string markupProblem(std::string_view markup);

// Occurrences of `needle` in `text`.
int countOccurrences(std::string_view text, std::string_view needle);

}  // namespace gib::test
