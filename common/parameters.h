// Declared parameters (pbrt's "one place turns a name into an object" habit): a table of
// parameter specs drives parsing of `key=value` assignments, error messages that name the
// parameter and its range, `gibench list`, and the metadata written with every output. A
// mistyped key is an error, never silently ignored.
#pragma once

#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace gib {

enum class ParameterType { kInteger, kNumber, kVector3, kChoice };

struct ParameterSpec {
  std::string name;
  ParameterType type = ParameterType::kNumber;
  std::string default_value;         // as the user would write it: "2", "0.9", "1,2,3", "pcf"
  double min = 0, max = 0;           // inclusive range of numbers (each component of a vector)
  std::vector<std::string> choices;  // kChoice only
  std::string unit;                  // "", "m", "degrees", "W/sr", ...
  std::string doc;                   // one line
};

using ParameterTable = std::vector<ParameterSpec>;

// A numeric (integer, number or vector) parameter in one call.
ParameterSpec numericParameter(std::string name, ParameterType type, std::string default_value,
                               double min, double max, std::string unit, std::string doc);
// A choice parameter.
ParameterSpec choiceParameter(std::string name, std::string default_value,
                              std::vector<std::string> choices, std::string doc);

// Validated values, every declared parameter present (defaults filled in).
class ParameterValues {
 public:
  double number(std::string_view name) const;
  int integer(std::string_view name) const;
  std::vector<double> vector3(std::string_view name) const;
  const std::string& text(std::string_view name) const;  // the canonical text of any parameter

  // Canonical "key=value" text of every parameter in table order, for metadata and hashing.
  std::vector<std::pair<std::string, std::string>> canonical() const;

 private:
  friend ParameterValues parseParameters(const ParameterTable&, const std::vector<std::string>&,
                                         std::string_view);
  const std::string& find(std::string_view name) const;
  std::vector<std::pair<std::string, std::string>> values_;
};

// Parses "key=value" assignments against the table. Throws gib::InputError naming `owner`
// ("scene 'chamber'", "technique 'direct'") for an unknown key (listing the known ones), a
// malformed value, a value out of range (giving the range), or a key given twice.
ParameterValues parseParameters(const ParameterTable& table,
                                const std::vector<std::string>& assignments,
                                std::string_view owner);

// One line per parameter for `gibench list`: "name (type, default D, range [a, b] unit): doc".
std::vector<std::string> describeParameters(const ParameterTable& table);

// The table as Markdown (parameter, type, default, range, meaning), for the documentation that
// `gibench list techniques --markdown` generates, so that no parameter table is written twice.
std::string parameterMarkdownTable(const ParameterTable& table);

}  // namespace gib
