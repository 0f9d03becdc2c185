#include "support/markup_check.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <vector>

namespace gib::test {

namespace {

constexpr std::array<std::string_view, 6> kVoidElements = {"meta", "link", "img",
                                                           "br",   "hr",   "input"};

std::string lower(std::string_view text) {
  std::string out(text);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return out;
}

}  // namespace

std::string markupProblem(std::string_view markup) {
  std::vector<std::string> open;
  std::size_t i = 0;
  while ((i = markup.find('<', i)) != std::string_view::npos) {
    if (markup.substr(i, 4) == "<!--") {
      i = markup.find("-->", i);
      if (i == std::string_view::npos) return "unterminated comment";
      continue;
    }
    const std::size_t end = markup.find('>', i);
    if (end == std::string_view::npos) return "unterminated tag at offset " + std::to_string(i);
    std::string_view tag = markup.substr(i + 1, end - i - 1);
    i = end + 1;
    if (tag.empty() || tag.front() == '!') continue;  // the doctype
    const bool closing = tag.front() == '/';
    if (closing) tag.remove_prefix(1);
    const bool self_closed = !closing && tag.back() == '/';
    const std::size_t name_end = tag.find_first_of(" \t\n/");
    const std::string name = lower(tag.substr(0, name_end));
    if (closing) {
      if (open.empty()) return "</" + name + "> closes nothing";
      if (open.back() != name) return "</" + name + "> closes <" + open.back() + ">";
      open.pop_back();
    } else if (!self_closed &&
               std::find(kVoidElements.begin(), kVoidElements.end(), name) == kVoidElements.end()) {
      open.push_back(name);
      if (name == "script" || name == "style") {  // raw text up to the end tag
        i = markup.find("</" + name, i);
        if (i == std::string_view::npos) return "<" + name + "> never closed";
      }
    }
  }
  if (!open.empty()) return "<" + open.back() + "> never closed";
  return {};
}

int countOccurrences(std::string_view text, std::string_view needle) {
  int count = 0;
  for (std::size_t i = text.find(needle); i != std::string_view::npos;
       i = text.find(needle, i + needle.size()))
    ++count;
  return count;
}

}  // namespace gib::test
