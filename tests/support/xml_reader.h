// Reads back the XML the project writes (the JUnit report) for tests: elements, attributes and
// character data with entity and character references decoded, as a conforming parser delivers
// them (attribute values normalised: a literal tab or line break reads as a space). Not a general
// parser: no DTD, CDATA sections or processing instructions besides the XML declaration.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace gib::test {

struct XmlElement {
  std::string name;
  std::vector<std::pair<std::string, std::string>> attributes;  // in document order
  std::vector<XmlElement> children;
  std::string text;  // the character data directly inside, concatenated

  // The value of an attribute, or nullptr.
  const std::string* attribute(std::string_view key) const;
  // The value of an attribute; "" when absent (the tests check presence separately).
  std::string at(std::string_view key) const;
  std::vector<const XmlElement*> childrenNamed(std::string_view child_name) const;
  // The first child of that name, or nullptr.
  const XmlElement* child(std::string_view child_name) const;
};

// The root element. Throws std::runtime_error with the byte offset of what is malformed
// (mismatched tags, an unknown entity, an unquoted attribute, text after the root).
XmlElement parseXml(std::string_view document);

}  // namespace gib::test
