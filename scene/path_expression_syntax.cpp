#include "scene/path_expression_syntax.h"

#include "common/input_error.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <string>

namespace gib::scene {

namespace {

constexpr const char* kEventsFix =
    "use L (light), D (diffuse or glossy), S (specular), P (medium), E (eye), with ( ) [ ] { } "
    "| * + ? and counts {n}, {n,}, {n,m}";

PathNode repetition(PathNode child, int min_count, int max_count) {
  PathNode node;
  node.kind = PathNode::Kind::kRepetition;
  node.children.push_back(std::move(child));
  node.min_count = min_count;
  node.max_count = max_count;
  return node;
}

// Groups several nodes into one, or returns the only one.
PathNode joined(PathNode::Kind kind, std::vector<PathNode> nodes) {
  if (nodes.size() == 1) return std::move(nodes.front());
  PathNode node;
  node.kind = kind;
  node.children = std::move(nodes);
  return node;
}

// Recursive descent over
//   alternation := concatenation ('|' concatenation)*
//   concatenation := repeated+
//   repeated := atom ('*' | '+' | '?' | '{' n '}' | '{' n ',' '}' | '{' n ',' m '}')?
//   atom := L | D | S | P | E | '(' alternation ')' | '[' alternation ']' | '{' alternation '}'
// where '{' after an atom opens a count when a digit follows it, and the book's "one or more"
// group otherwise. Whitespace is skipped everywhere.
class Parser {
 public:
  explicit Parser(std::string_view text) : text_(text) {}

  PathNode parseAll() {
    std::optional<PathNode> root = parseAlternation();
    if (!atEnd()) {
      const char c = peek();
      fail(column(), fmt::format("'{}' closes nothing", c),
           fmt::format("remove it or add the '{}' it closes", openerOf(c)));
    }
    if (!root) fail(1, "there is no event", "write a path class such as LDE or L(D|S|P)*E");
    return std::move(*root);
  }

 private:
  [[noreturn]] void fail(int column, const std::string& problem, const std::string& fix) const {
    throw InputError(
        fmt::format("path expression '{}': column {}: {}; {}", text_, column, problem, fix));
  }

  void skipSpace() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
  }
  bool atEnd() {
    skipSpace();
    return pos_ == text_.size();
  }
  char peek() { return atEnd() ? '\0' : text_[pos_]; }
  int column() {
    skipSpace();
    return static_cast<int>(pos_) + 1;
  }
  static char openerOf(char closer) { return closer == ')' ? '(' : closer == ']' ? '[' : '{'; }
  static bool isCloser(char c) { return c == ')' || c == ']' || c == '}'; }
  // Whether the '{' at pos_ opens a count rather than a group.
  bool countFollows() {
    std::size_t next = pos_ + 1;
    while (next < text_.size() && std::isspace(static_cast<unsigned char>(text_[next]))) ++next;
    return next < text_.size() && std::isdigit(static_cast<unsigned char>(text_[next]));
  }

  std::optional<PathNode> parseAlternation() {
    std::optional<PathNode> first = parseConcatenation();
    if (peek() != '|') return first;
    std::vector<PathNode> choices;
    while (peek() == '|') {
      const int bar = column();
      if (!first)
        fail(bar, "'|' has nothing on its left",
             "write an event or a group on both sides of '|', e.g. L(D|S)E");
      choices.push_back(std::move(*first));
      ++pos_;
      first = parseConcatenation();
      if (!first)
        fail(bar, "'|' has nothing on its right",
             "write an event or a group on both sides of '|', e.g. L(D|S)E");
    }
    choices.push_back(std::move(*first));
    return joined(PathNode::Kind::kAlternation, std::move(choices));
  }

  std::optional<PathNode> parseConcatenation() {
    std::vector<PathNode> parts;
    while (!atEnd() && peek() != '|' && !isCloser(peek())) parts.push_back(parseRepeated());
    if (parts.empty()) return std::nullopt;
    return joined(PathNode::Kind::kConcatenation, std::move(parts));
  }

  PathNode parseRepeated() {
    PathNode atom = parseAtom();
    const int at = column();
    const char c = peek();
    if (c == '*' || c == '+' || c == '?') {
      ++pos_;
      atom = repetition(std::move(atom), c == '+' ? 1 : 0, c == '?' ? 1 : kUnboundedCount);
    } else if (c == '{' && countFollows()) {
      atom = parseCount(std::move(atom));
    } else {
      return atom;
    }
    // A second repetition reads as a lazy or possessive quantifier elsewhere (D+?); refusing it
    // keeps every expression meaning what it would mean in a textbook.
    const char again = peek();
    if (again == '*' || again == '+' || again == '?' || (again == '{' && countFollows()))
      fail(column(), fmt::format("'{}' follows the repetition at column {}", again, at),
           "put the repeated part in parentheses, e.g. (D+)?");
    return atom;
  }

  PathNode parseAtom() {
    const int at = column();
    const char c = peek();
    switch (c) {
      case 'L':
        ++pos_;
        return event(PathEvent::kLight);
      case 'D':
        ++pos_;
        return event(PathEvent::kDiffuse);
      case 'S':
        ++pos_;
        return event(PathEvent::kSpecular);
      case 'P':
        ++pos_;
        return event(PathEvent::kMedium);
      case 'E':
        ++pos_;
        return event(PathEvent::kEye);
      case '(':
        return parseGroup(at, ')');
      case '[':
        return repetition(parseGroup(at, ']'), 0, 1);
      case '{':
        if (countFollows())
          fail(at, "the count repeats nothing", "put it after an event or a group, e.g. LD{2}E");
        return repetition(parseGroup(at, '}'), 1, kUnboundedCount);
      case '*':
      case '+':
      case '?':
        fail(at, fmt::format("'{}' repeats nothing", c),
             "put it after an event or a group, e.g. LD*E");
      default:
        fail(at, fmt::format("'{}' is not an event", c), kEventsFix);
    }
  }

  static PathNode event(PathEvent e) {
    PathNode node;
    node.event = e;
    return node;
  }

  PathNode parseGroup(int open_column, char closer) {
    const char opener = text_[pos_];
    ++pos_;
    std::optional<PathNode> inner = parseAlternation();
    if (atEnd())
      fail(open_column, fmt::format("'{}' is not closed", opener),
           fmt::format("add '{}' after the group", closer));
    if (peek() != closer)
      fail(column(),
           fmt::format("'{}' does not close the '{}' at column {}", peek(), opener, open_column),
           fmt::format("close it with '{}'", closer));
    if (!inner)
      fail(open_column, fmt::format("'{}{}' holds no event", opener, closer),
           "put events in the group or remove it");
    ++pos_;
    return std::move(*inner);
  }

  // A count in digits at pos_, at most kMaxPathCount.
  int parseNumber() {
    const int at = column();
    long long value = 0;
    bool any = false;
    while (!atEnd() && std::isdigit(static_cast<unsigned char>(peek()))) {
      value = std::min<long long>(value * 10 + (peek() - '0'), kMaxPathCount + 1LL);
      ++pos_;
      any = true;
    }
    if (!any)
      fail(at, "the count's upper bound is not a number",
           "write {n}, {n,} or {n,m} with whole numbers");
    if (value > kMaxPathCount)
      fail(at, fmt::format("a count above {} is refused", kMaxPathCount),
           "write * or {n,} for paths of any length");
    return static_cast<int>(value);
  }

  PathNode parseCount(PathNode atom) {
    const int open = column();
    ++pos_;  // '{'
    const int min_count = parseNumber();
    int max_count = min_count;
    if (peek() == ',') {
      ++pos_;
      max_count = peek() == '}' ? kUnboundedCount : parseNumber();
    }
    if (peek() != '}')
      fail(open, "the count is not {n}, {n,} or {n,m}", "close it with '}', e.g. D{2} or D{1,3}");
    ++pos_;
    if (min_count > max_count)
      fail(open,
           fmt::format("the count {{{},{}}} has its minimum above its maximum", min_count,
                       max_count),
           fmt::format("write {{{},{}}}", max_count, min_count));
    return repetition(std::move(atom), min_count, max_count);
  }

  std::string_view text_;
  std::size_t pos_ = 0;
};

// The bounce-range arithmetic: counts saturate at kUnboundedCount, and a finite range beyond
// kMaxPathCount is left to the general automaton (which refuses it as too large).
long long product(long long count, long long times) {
  if (count == kUnboundedCount || times == kUnboundedCount)
    return count == 0 || times == 0 ? 0 : kUnboundedCount;
  return count * times;
}
long long sum(long long a, long long b) {
  return a == kUnboundedCount || b == kUnboundedCount ? kUnboundedCount : a + b;
}
std::optional<BounceRange> rangeOf(long long min, long long max) {
  if (max != kUnboundedCount && max > kMaxPathCount) return std::nullopt;
  return BounceRange{static_cast<int>(min), static_cast<int>(max)};
}

// The range when `node` matches exactly the strings over {D, S, P} of min..max letters.
std::optional<BounceRange> vertexRangeOf(const PathNode& node) {
  switch (node.kind) {
    case PathNode::Kind::kEvent:
      return std::nullopt;  // one letter alone is not every vertex
    case PathNode::Kind::kConcatenation: {
      long long min = 0, max = 0;
      for (const PathNode& child : node.children) {
        const std::optional<BounceRange> r = vertexRangeOf(child);
        if (!r) return std::nullopt;
        min = sum(min, r->min);
        max = sum(max, r->max);
      }
      return rangeOf(min, max);
    }
    case PathNode::Kind::kAlternation: {
      // Single letters must together be D, S and P (one vertex of any kind); the other choices
      // must be ranges, and all of them together one range without a gap.
      bool letters[3] = {false, false, false};
      bool any_letter = false;
      std::vector<BounceRange> ranges;
      for (const PathNode& child : node.children) {
        if (child.kind == PathNode::Kind::kEvent) {
          if (child.event == PathEvent::kLight || child.event == PathEvent::kEye)
            return std::nullopt;
          letters[static_cast<int>(child.event) - 1] = any_letter = true;
        } else if (std::optional<BounceRange> r = vertexRangeOf(child)) {
          ranges.push_back(*r);
        } else {
          return std::nullopt;
        }
      }
      if (any_letter) {
        if (!(letters[0] && letters[1] && letters[2])) return std::nullopt;
        ranges.push_back({1, 1});
      }
      std::sort(ranges.begin(), ranges.end(),
                [](const BounceRange& a, const BounceRange& b) { return a.min < b.min; });
      BounceRange merged = ranges.front();
      for (const BounceRange& r : ranges) {
        if (merged.max != kUnboundedCount && r.min > merged.max + 1) return std::nullopt;
        merged.max = std::max(merged.max, r.max);
      }
      return merged;
    }
    case PathNode::Kind::kRepetition: {
      const std::optional<BounceRange> r = vertexRangeOf(node.children.front());
      if (!r) return std::nullopt;
      // k repeats of min..max letters give every length in k·min..k·max; the union over
      // k = first..last has no gap when each k's range reaches the next one's start,
      // (k + 1)·min ≤ k·max + 1, which holds for every k from `first` on if it holds at `first`.
      const long long first = node.min_count, last = node.max_count;
      if (first != last) {
        const bool reaches =
            first == 0 ? r->min <= 1
                       : r->max == kUnboundedCount || (first + 1) * r->min <= first * r->max + 1;
        if (!reaches) return std::nullopt;
      }
      return rangeOf(product(r->min, first), product(r->max, last));
    }
  }
  return std::nullopt;
}

}  // namespace

PathNode parsePathSyntax(std::string_view text) {
  return Parser(text).parseAll();
}

std::optional<BounceRange> bounceRangeOf(const PathNode& root) {
  if (root.kind != PathNode::Kind::kConcatenation) return std::nullopt;
  const std::vector<PathNode>& parts = root.children;
  auto is = [](const PathNode& node, PathEvent e) {
    return node.kind == PathNode::Kind::kEvent && node.event == e;
  };
  if (!is(parts.front(), PathEvent::kLight) || !is(parts.back(), PathEvent::kEye))
    return std::nullopt;
  if (parts.size() == 2) return BounceRange{0, 0};
  PathNode middle;
  middle.kind = PathNode::Kind::kConcatenation;
  middle.children.assign(parts.begin() + 1, parts.end() - 1);
  return vertexRangeOf(middle);
}

}  // namespace gib::scene
