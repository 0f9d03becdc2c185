#include "scene/path_expression.h"

#include "common/input_error.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cctype>
#include <chrono>
#include <regex>
#include <string>
#include <vector>

namespace gib::scene {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;

// Every string over {D, S, P} of up to this many letters is checked; the test expressions' counts
// stay below it, so each is seen both matching and failing at every count.
constexpr int kMaxVertices = 7;

// The expressions of the issue and the book, in every syntactic form.
const std::vector<std::string> kExpressions = {"L(D|S|P)*E",
                                               "LS+DE",
                                               "LDSE",
                                               "LD*E",
                                               "L(D|S)*S(D|S)*E",
                                               "L[{D|S|P}]E",
                                               "L{D}DE",
                                               "L [ { D } ] E",
                                               "L{S}D{S}E",
                                               "LS{2}DE",
                                               "LD{1,3}E",
                                               "L(D|S){2,}E",
                                               "LP?D{0,2}E",
                                               "L(DS|SD)+E",
                                               "LE|LSE",
                                               "L(D|S|P){2,4}E",
                                               "L(S|D|P)(D|S|P)*E",
                                               "L((D|S|P){2}){1,2}E",
                                               "L(D|S|P)?E"};

PathEvent eventOf(char c) {
  switch (c) {
    case 'L':
      return PathEvent::kLight;
    case 'D':
      return PathEvent::kDiffuse;
    case 'S':
      return PathEvent::kSpecular;
    case 'P':
      return PathEvent::kMedium;
    default:
      return PathEvent::kEye;
  }
}

std::vector<PathEvent> eventsOf(const std::string& path) {
  std::vector<PathEvent> events;
  for (char c : path) events.push_back(eventOf(c));
  return events;
}

// The independent oracle: the expression as an ECMAScript regular expression. Only the book's
// forms differ: [X] is (?:X)? and {X} (X not a count) is (?:X)+.
std::regex oracleOf(const std::string& expression) {
  std::string out;
  std::vector<std::string> closers;
  for (std::size_t i = 0; i < expression.size(); ++i) {
    const char c = expression[i];
    if (std::isspace(static_cast<unsigned char>(c))) continue;
    std::size_t next = i + 1;
    while (next < expression.size() && std::isspace(static_cast<unsigned char>(expression[next])))
      ++next;
    if (c == '{' && next < expression.size() && std::isdigit(expression[next])) {
      const std::size_t end = expression.find('}', i);
      out += expression.substr(i, end - i + 1);
      i = end;
    } else if (c == '[' || c == '{' || c == '(') {
      out += c == '(' ? "(" : "(?:";
      closers.push_back(c == '[' ? ")?" : c == '{' ? ")+" : ")");
    } else if (c == ']' || c == '}' || c == ')') {
      out += closers.back();
      closers.pop_back();
    } else {
      out += c;
    }
  }
  return std::regex(out, std::regex::ECMAScript);
}

// Every middle part of up to kMaxVertices vertices, shortest first.
std::vector<std::string> allMiddles() {
  std::vector<std::string> middles = {""};
  for (std::size_t i = 0; i < middles.size(); ++i)
    if (middles[i].size() < kMaxVertices)
      for (char v : {'D', 'S', 'P'}) middles.push_back(middles[i] + v);
  return middles;
}

// The middle read by the eye's automaton (E first, so the last vertex first) and the light's.
bool eyeAccepts(const PathExpression& e, const std::string& middle) {
  int state = e.eyeStart();
  for (auto it = middle.rbegin(); it != middle.rend(); ++it) state = e.eyeStep(state, eventOf(*it));
  return e.eyeAcceptsLight(state);
}
bool lightAccepts(const PathExpression& e, const std::string& middle) {
  int state = e.lightStart();
  for (char v : middle) state = e.lightStep(state, eventOf(v));
  return e.lightAcceptsEye(state);
}

TEST(PathExpression, MatchesWhatTheRegexOracleMatchesAndBothAutomataAgree) {
  const std::vector<std::string> middles = allMiddles();
  ASSERT_EQ(middles.size(), 3280u);  // 3^0 + … + 3^7
  for (const std::string& text : kExpressions) {
    SCOPED_TRACE(text);
    const PathExpression e = PathExpression::parse(text);
    const std::regex oracle = oracleOf(text);
    int matched = 0;
    for (const std::string& middle : middles) {
      const std::string path = "L" + middle + "E";
      const bool expected = std::regex_match(path, oracle);
      ASSERT_EQ(e.matches(eventsOf(path)), expected) << path;
      ASSERT_EQ(eyeAccepts(e, middle), expected) << path;
      ASSERT_EQ(lightAccepts(e, middle), expected) << path;
      matched += expected;
    }
    EXPECT_GT(matched, 0);
    // Malformed paths match nothing, as the oracle says for these expressions.
    for (const std::string bad : {"", "L", "E", "DE", "LD", "EL", "LEE", "LLDE", "LDLE", "ELDL"}) {
      EXPECT_FALSE(e.matches(eventsOf(bad))) << bad;
      EXPECT_FALSE(std::regex_match(bad, oracle)) << bad;
    }
  }
}

// Whether some middle of up to `extra` more vertices, read after `prefix` from the eye, accepts.
bool someExtensionAccepts(const PathExpression& e, const std::string& eye_prefix, int extra) {
  std::vector<std::string> tails = {""};
  for (std::size_t i = 0; i < tails.size(); ++i) {
    const std::string middle = eye_prefix + tails[i];
    if (eyeAccepts(e, std::string(middle.rbegin(), middle.rend()))) return true;
    if (static_cast<int>(tails[i].size()) < extra)
      for (char v : {'D', 'S', 'P'}) tails.push_back(tails[i] + v);
  }
  return false;
}

TEST(PathExpression, AStateIsDeadExactlyWhenNoPathThroughItCanMatch) {
  for (const std::string& text : kExpressions) {
    SCOPED_TRACE(text);
    const PathExpression e = PathExpression::parse(text);
    std::vector<std::string> prefixes = {""};
    for (std::size_t i = 0; i < prefixes.size(); ++i) {
      const std::string prefix = prefixes[i];  // vertices in the order the eye meets them
      int state = e.eyeStart();
      for (char v : prefix) state = e.eyeStep(state, eventOf(v));
      EXPECT_EQ(state != PathExpression::kDead, someExtensionAccepts(e, prefix, 4)) << prefix;
      if (prefix.size() < 4)
        for (char v : {'D', 'S', 'P'}) prefixes.push_back(prefix + v);
    }
  }
}

TEST(PathExpression, CausticsSeenFromTheEyeDieAtTheSecondDiffuseVertex) {
  const PathExpression caustics = PathExpression::parse("LS+DE");
  int state = caustics.eyeStep(caustics.eyeStart(), PathEvent::kDiffuse);
  EXPECT_NE(state, PathExpression::kDead);
  EXPECT_FALSE(caustics.eyeAcceptsLight(state));  // L D E is direct lighting, not a caustic
  state = caustics.eyeStep(state, PathEvent::kDiffuse);
  EXPECT_EQ(state, PathExpression::kDead);
  EXPECT_EQ(caustics.eyeStep(state, PathEvent::kSpecular), PathExpression::kDead);
  EXPECT_FALSE(caustics.eyeAcceptsLight(state));
}

TEST(PathExpression, BounceClassesMatchExactlyTheirVertexCounts) {
  const std::vector<std::string> middles = allMiddles();
  const std::vector<std::pair<int, int>> ranges = {
      {0, 0}, {0, 1}, {1, 1}, {2, 5}, {0, PathClass::kUnlimited}, {3, PathClass::kUnlimited}};
  for (const auto& [min, max] : ranges) {
    SCOPED_TRACE(bounceExpressionText(min, max));
    const PathExpression e = PathExpression::ofBounces(min, max);
    for (const std::string& middle : middles) {
      const int n = static_cast<int>(middle.size());
      ASSERT_EQ(e.matches(eventsOf("L" + middle + "E")), n >= min && n <= max) << middle;
      ASSERT_EQ(eyeAccepts(e, middle), n >= min && n <= max) << middle;
    }
  }
}

TEST(PathExpression, LargeBounceCountsTakeConstantTimeAndMemory) {
  const auto start = std::chrono::steady_clock::now();
  const PathExpression up_to_a_million = PathExpression::ofBounces(0, 1000000);
  const PathExpression from_three = PathExpression::ofBounces(3, PathClass::kUnlimited);
  // The same classes written out by a user, and a million-vertex bound read as a count.
  const PathExpression written = PathExpression::parse("L(D|S|P){0,1000000}E");
  const PathExpression book = PathExpression::parse("L(D|S|P)(D|S|P){(D|S|P)}E");
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(seconds, 0.05);  // a table per vertex count would take longer and ~12 MB
  EXPECT_LE(sizeof(up_to_a_million), 256u);

  int state = up_to_a_million.eyeStart(), written_state = written.eyeStart();
  for (int vertex = 0; vertex < 1000000; ++vertex) {
    state = up_to_a_million.eyeStep(state, PathEvent::kSpecular);
    written_state = written.eyeStep(written_state, PathEvent::kDiffuse);
  }
  EXPECT_TRUE(up_to_a_million.eyeAcceptsLight(state));
  EXPECT_TRUE(written.eyeAcceptsLight(written_state));
  EXPECT_EQ(up_to_a_million.eyeStep(state, PathEvent::kDiffuse), PathExpression::kDead);
  EXPECT_EQ(written.eyeStep(written_state, PathEvent::kDiffuse), PathExpression::kDead);

  for (const PathExpression* e : {&from_three, &book}) {
    int s = e->lightStart();
    for (int vertex = 0; vertex < 3; ++vertex) {
      EXPECT_FALSE(e->lightAcceptsEye(s)) << e->text();
      s = e->lightStep(s, PathEvent::kMedium);
    }
    for (int vertex = 0; vertex < 100; ++vertex) s = e->lightStep(s, PathEvent::kDiffuse);
    EXPECT_TRUE(e->lightAcceptsEye(s)) << e->text();
  }
}

TEST(PathExpression, LargeCountsOutsideABounceRangeAreRefusedQuickly) {
  const auto start = std::chrono::steady_clock::now();
  for (const std::string text : {"LS{0,1000000}DE", "L((D|S){1000}){1000}E"}) {
    SCOPED_TRACE(text);
    try {
      PathExpression::parse(text);
      ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
      EXPECT_THAT(e.what(), HasSubstr("is too large to compile"));
    }
  }
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 2.0);
  // A moderate count compiles.
  EXPECT_TRUE(PathExpression::parse("LS{0,300}DE").matches(eventsOf("LSSSDE")));
}

// The message of parsing `text`, which must fail.
std::string errorOf(const std::string& text) {
  try {
    PathExpression::parse(text);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "'" << text << "' parsed";
  return "";
}

TEST(PathExpression, SyntaxErrorsPointAtTheirColumn) {
  struct Case {
    std::string text;
    int column;
    std::string problem;
  };
  const std::vector<Case> cases = {
      {"L(D", 2, "'(' is not closed"},
      {"L(D|S", 2, "'(' is not closed"},
      {"LXE", 2, "'X' is not an event"},
      {"L D X", 5, "'X' is not an event"},  // columns count the text as given
      {"lde", 1, "'l' is not an event"},
      {"L(D|)E", 4, "'|' has nothing on its right"},
      {"|LE", 1, "'|' has nothing on its left"},
      {"LE|", 3, "'|' has nothing on its right"},
      {"*LE", 1, "'*' repeats nothing"},
      {"L(+D)E", 3, "'+' repeats nothing"},
      {"{2}LE", 1, "the count repeats nothing"},
      {"LD{3,1}E", 3, "the count {3,1} has its minimum above its maximum"},
      {"LD{2000000}E", 4, "a count above 1000000 is refused"},
      {"LD{2E", 3, "the count is not {n}, {n,} or {n,m}"},
      {"L)E", 2, "')' closes nothing"},
      {"L(D]E", 4, "']' does not close the '(' at column 2"},
      {"L()E", 2, "'()' holds no event"},
      {"LD+?E", 4, "'?' follows the repetition at column 3"},
      {"", 1, "there is no event"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.text);
    const std::string message = errorOf(c.text);
    EXPECT_THAT(message, StartsWith("path expression '" + c.text + "': column " +
                                    std::to_string(c.column) + ": " + c.problem + "; "));
    EXPECT_EQ(message.find('\n'), std::string::npos);
  }
}

TEST(PathExpression, ExpressionsNoLightPathMatchesAreRefused) {
  for (const std::string text : {"DE", "LE E", "L", "E", "LD", "EDL", "LEDE", "(D|S)*E", "L{2}E"}) {
    SCOPED_TRACE(text);
    EXPECT_THAT(errorOf(text),
                StartsWith("path expression '" + text +
                           "' matches no light path (every path is L, then D, S or P vertices, "
                           "then E); "));
  }
}

TEST(PathExpression, TextIsAsGivenWithoutWhitespace) {
  EXPECT_EQ(PathExpression::parse(" L [ {D|S|P} ] E ").text(), "L[{D|S|P}]E");
  EXPECT_EQ(PathExpression::parse("LS + D E").text(), "LS+DE");
}

TEST(PathExpression, OfBouncesRefusesAnEmptyRange) {
  EXPECT_THROW(PathExpression::ofBounces(2, 1), InputError);
  EXPECT_THROW(PathExpression::ofBounces(-1, 1), InputError);
}

TEST(PathClass, DescriptionParsesBackToTheSameClass) {
  const std::vector<std::string> middles = allMiddles();
  const std::vector<PathClass> classes = {{0, 0},
                                          {0, 1},
                                          {1, 1},
                                          {0, 2},
                                          {2, 2},
                                          {2, 5},
                                          {1, 3},
                                          {},
                                          {1, PathClass::kUnlimited},
                                          {2, PathClass::kUnlimited},
                                          {0, 1000000}};
  for (const PathClass& c : classes) {
    const std::string text = describePathClass(c);
    SCOPED_TRACE(text);
    const PathExpression described = PathExpression::parse(text);
    EXPECT_EQ(described.text(), text);
    for (const std::string& middle : middles) {
      const int n = static_cast<int>(middle.size());
      ASSERT_EQ(described.matches(eventsOf("L" + middle + "E")), c.contains(n)) << middle;
    }
  }
  EXPECT_EQ(describePathClass({0, 1}), "L(D|S|P){0,1}E");
  EXPECT_EQ(describePathClass({}), "L(D|S|P)*E");
  EXPECT_EQ(describePathClass({0, 0}), "LE");
  PathClass caustics;
  caustics.expression = "LS+DE";
  EXPECT_EQ(describePathClass(caustics), "LS+DE");
}

TEST(PathClass, CompilesItsExpressionOrItsBounces) {
  PathClass caustics;
  caustics.expression = "LS+DE";
  EXPECT_TRUE(compilePathClass(caustics).matches(eventsOf("LSSDE")));
  EXPECT_FALSE(compilePathClass(caustics).matches(eventsOf("LDE")));
  EXPECT_TRUE(compilePathClass({1, 1}).matches(eventsOf("LSE")));
  EXPECT_FALSE(compilePathClass({1, 1}).matches(eventsOf("LSDE")));
  caustics.max_bounces = 3;
  EXPECT_THROW(compilePathClass(caustics), InputError);
}

}  // namespace
}  // namespace gib::scene
