// Text for HTML and SVG: escaping, and links to files of a run directory. Job ids and parameter
// values carry '/', '=', ',', '<', '&' and quotes, so nothing from results goes out unescaped.
#pragma once

#include <string>
#include <string_view>

namespace gib::reports {

// Escapes &, <, >, " and ' for element text and for quoted attribute values (HTML and SVG).
std::string escapeHtml(std::string_view text);

// A relative or absolute file path as a URL path: every byte outside the unreserved set
// (RFC 3986: letters, digits, '-', '.', '_', '~') and '/' percent-encoded, so that '#', '?', '%'
// and spaces in a slug or an output path still name the file. Still needs escapeHtml in an
// attribute (it leaves nothing that would need it, but the rule stays simple).
std::string urlPath(std::string_view path);

}  // namespace gib::reports
