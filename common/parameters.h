// Declared parameters (pbrt's "one place turns a name into an object" habit): a table of
// parameter specs drives parsing of `key=value` assignments, error messages that name the
// parameter and its range, `gibench list`, and the metadata written with every output. A
// mistyped key is an error, never silently ignored.
#pragma once

#include <initializer_list>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace gib {

// kBoolean is written "true" or "false"; kIntegerChoice is an integer from a list ("64", "128",
// …: an atlas resolution), read with integer(); kText is any non-empty text (a file's path, or a
// keyword the reader checks itself), read with text().
enum class ParameterType { kInteger, kNumber, kVector3, kChoice, kBoolean, kIntegerChoice, kText };

struct ParameterSpec {
  std::string name;
  ParameterType type = ParameterType::kNumber;
  std::string default_value;         // as the user would write it: "2", "0.9", "1,2,3", "pcf"
  double min = 0, max = 0;           // inclusive range of numbers (each component of a vector)
  std::vector<std::string> choices;  // kChoice and kIntegerChoice only
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
// A switch, "true" or "false".
ParameterSpec booleanParameter(std::string name, bool default_value, std::string doc);
// Free text (a file's path); the code that reads it checks what it names.
ParameterSpec textParameter(std::string name, std::string default_value, std::string doc);
// An integer from a list (a power-of-two resolution).
ParameterSpec integerChoiceParameter(std::string name, int default_value, std::vector<int> choices,
                                     std::string unit, std::string doc);

// The one way to compose a table from parts (a technique's own parameters and a shared block):
// the parts in order. Throws std::logic_error when two parts declare the same name, a mistake in
// the code that declares them.
ParameterTable joinParameterTables(std::initializer_list<ParameterTable> parts);

// Validated values, every declared parameter present (defaults filled in).
// The typed accessors check the declared type: reading a parameter as another type (integer() of
// a choice, boolean() of a number) throws std::logic_error, a mistake in the code that reads it.
class ParameterValues {
 public:
  double number(std::string_view name) const;  // kNumber or kInteger
  int integer(std::string_view name) const;    // kInteger or kIntegerChoice
  bool boolean(std::string_view name) const;   // kBoolean
  std::vector<double> vector3(std::string_view name) const;
  const std::string& text(std::string_view name) const;  // the canonical text of any parameter

  // Canonical "key=value" text of every parameter in table order, for metadata and hashing.
  std::vector<std::pair<std::string, std::string>> canonical() const;

 private:
  friend ParameterValues parseParameters(const ParameterTable&, const std::vector<std::string>&,
                                         std::string_view);
  const std::string& find(std::string_view name, std::initializer_list<ParameterType> types) const;
  std::vector<std::pair<std::string, std::string>> values_;
  std::vector<ParameterType> types_;  // values_[i]'s declared type
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
