// Text for XML 1.0 documents (the JUnit report): job ids carry '/', '=', ',' and '&', failure
// messages quotes and '<', and a failed task's log may hold terminal escapes or broken UTF-8,
// none of which may reach a CI tool's parser unescaped.
#pragma once

#include <string>
#include <string_view>

namespace gib::reports {

// Escapes &, <, >, " and ' as entities. ASCII control characters other than tab, line feed and
// carriage return (XML 1.0 cannot carry them, bar DEL), bytes that are not UTF-8, U+FFFE and
// U+FFFF become U+FFFD. In an attribute value (`attribute`), tab, line feed and carriage return
// become character references, since a parser would turn them into spaces; in element text only
// the carriage return does (a parser would drop it).
std::string escapeXml(std::string_view text, bool attribute);

}  // namespace gib::reports
