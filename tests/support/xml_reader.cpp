#include "support/xml_reader.h"

#include <cstdint>
#include <stdexcept>
#include <string>

namespace gib::test {

namespace {

class Reader {
 public:
  explicit Reader(std::string_view text) : text_(text) {}

  XmlElement document() {
    skipProlog();
    XmlElement root = element();
    skipMisc();
    if (pos_ != text_.size()) fail("content after the root element");
    return root;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error("XML at byte " + std::to_string(pos_) + ": " + what);
  }

  bool startsWith(std::string_view prefix) const {
    return text_.substr(pos_, prefix.size()) == prefix;
  }

  void expect(std::string_view literal) {
    if (!startsWith(literal)) fail("expected '" + std::string(literal) + "'");
    pos_ += literal.size();
  }

  void skipSpace() {
    while (pos_ < text_.size() &&
           std::string_view(" \t\r\n").find(text_[pos_]) != std::string_view::npos)
      ++pos_;
  }

  void skipUntilAfter(std::string_view end) {
    const std::size_t found = text_.find(end, pos_);
    if (found == std::string_view::npos) fail("unterminated '" + std::string(end) + "'");
    pos_ = found + end.size();
  }

  // Comments and white space between top-level parts.
  void skipMisc() {
    for (;;) {
      skipSpace();
      if (!startsWith("<!--")) return;
      skipUntilAfter("-->");
    }
  }

  void skipProlog() {
    if (startsWith("<?xml")) skipUntilAfter("?>");
    skipMisc();
  }

  std::string name() {
    const std::size_t start = pos_;
    while (pos_ < text_.size() &&
           std::string_view(" \t\r\n=/>\"'<&").find(text_[pos_]) == std::string_view::npos)
      ++pos_;
    if (pos_ == start) fail("expected a name");
    return std::string(text_.substr(start, pos_ - start));
  }

  static void appendUtf8(std::uint32_t code, std::string& out) {
    if (code < 0x80) {
      out += char(code);
    } else if (code < 0x800) {
      out += char(0xC0 | (code >> 6));
      out += char(0x80 | (code & 0x3F));
    } else if (code < 0x10000) {
      out += char(0xE0 | (code >> 12));
      out += char(0x80 | ((code >> 6) & 0x3F));
      out += char(0x80 | (code & 0x3F));
    } else {
      out += char(0xF0 | (code >> 18));
      out += char(0x80 | ((code >> 12) & 0x3F));
      out += char(0x80 | ((code >> 6) & 0x3F));
      out += char(0x80 | (code & 0x3F));
    }
  }

  // After '&': an entity or character reference, decoded onto `out`.
  void reference(std::string& out) {
    const std::size_t end = text_.find(';', pos_);
    if (end == std::string_view::npos) fail("unterminated reference");
    const std::string_view ref = text_.substr(pos_, end - pos_);
    if (ref == "amp")
      out += '&';
    else if (ref == "lt")
      out += '<';
    else if (ref == "gt")
      out += '>';
    else if (ref == "quot")
      out += '"';
    else if (ref == "apos")
      out += '\'';
    else if (ref.size() > 1 && ref[0] == '#') {
      const bool hex = ref[1] == 'x';
      const std::string digits(ref.substr(hex ? 2 : 1));
      if (digits.empty()) fail("empty character reference");
      std::size_t used = 0;
      const unsigned long code = std::stoul(digits, &used, hex ? 16 : 10);
      if (used != digits.size()) fail("malformed character reference");
      appendUtf8(std::uint32_t(code), out);
    } else {
      fail("unknown entity '&" + std::string(ref) + ";'");
    }
    pos_ = end + 1;
  }

  std::string attributeValue() {
    const char quote = pos_ < text_.size() ? text_[pos_] : '\0';
    if (quote != '"' && quote != '\'') fail("attribute value without quotes");
    ++pos_;
    std::string value;
    for (;;) {
      if (pos_ >= text_.size()) fail("unterminated attribute value");
      const char c = text_[pos_++];
      if (c == quote) return value;
      if (c == '<') fail("'<' in an attribute value");
      if (c == '&')
        reference(value);
      else
        value += (c == '\t' || c == '\n' || c == '\r') ? ' ' : c;
    }
  }

  XmlElement element() {
    expect("<");
    XmlElement e;
    e.name = name();
    for (;;) {
      skipSpace();
      if (startsWith("/>")) {
        pos_ += 2;
        return e;
      }
      if (startsWith(">")) {
        ++pos_;
        break;
      }
      std::string key = name();
      skipSpace();
      expect("=");
      skipSpace();
      for (const auto& [existing, value] : e.attributes)
        if (existing == key) fail("attribute '" + key + "' given twice");
      e.attributes.emplace_back(std::move(key), attributeValue());
    }
    for (;;) {
      if (pos_ >= text_.size()) fail("<" + e.name + "> never closed");
      if (startsWith("</")) {
        pos_ += 2;
        if (name() != e.name) fail("end tag does not close <" + e.name + ">");
        skipSpace();
        expect(">");
        return e;
      }
      if (startsWith("<!--")) {
        skipUntilAfter("-->");
      } else if (startsWith("<")) {
        e.children.push_back(element());
      } else if (text_[pos_] == '&') {
        ++pos_;
        reference(e.text);
      } else {
        if (text_[pos_] == '>' && pos_ >= 2 && text_.substr(pos_ - 2, 2) == "]]")
          fail("']]>' in character data");
        e.text += text_[pos_++];
      }
    }
  }

  std::string_view text_;
  std::size_t pos_ = 0;
};

}  // namespace

const std::string* XmlElement::attribute(std::string_view key) const {
  for (const auto& [name, value] : attributes)
    if (name == key) return &value;
  return nullptr;
}

std::string XmlElement::at(std::string_view key) const {
  const std::string* value = attribute(key);
  return value ? *value : std::string();
}

std::vector<const XmlElement*> XmlElement::childrenNamed(std::string_view child_name) const {
  std::vector<const XmlElement*> found;
  for (const XmlElement& c : children)
    if (c.name == child_name) found.push_back(&c);
  return found;
}

const XmlElement* XmlElement::child(std::string_view child_name) const {
  for (const XmlElement& c : children)
    if (c.name == child_name) return &c;
  return nullptr;
}

XmlElement parseXml(std::string_view document) {
  return Reader(document).document();
}

}  // namespace gib::test
