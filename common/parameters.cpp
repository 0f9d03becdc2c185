#include "common/parameters.h"

#include "common/input_error.h"
#include "common/join.h"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace gib {

namespace {

const char* typeName(ParameterType type) {
  switch (type) {
    case ParameterType::kInteger:
      return "integer";
    case ParameterType::kNumber:
      return "number";
    case ParameterType::kVector3:
      return "x,y,z";
    case ParameterType::kChoice:
      return "choice";
    case ParameterType::kBoolean:
      return "boolean";
    case ParameterType::kIntegerChoice:
      return "integer choice";
    case ParameterType::kText:
      return "text";
  }
  return "?";
}

bool hasChoices(ParameterType type) {
  return type == ParameterType::kChoice || type == ParameterType::kBoolean ||
         type == ParameterType::kIntegerChoice;
}

std::string rangeText(const ParameterSpec& spec) {
  if (hasChoices(spec.type)) return joinNames(spec.choices, "|");
  if (spec.type == ParameterType::kText) return "any text";
  return fmt::format("[{}, {}]{}{}", spec.min, spec.max, spec.unit.empty() ? "" : " ", spec.unit);
}

bool parseDouble(const std::string& text, double& value) {
  if (text.empty()) return false;
  char* end = nullptr;
  errno = 0;
  value = std::strtod(text.c_str(), &end);
  return errno == 0 && end == text.c_str() + text.size() && std::isfinite(value);
}

// Returns the canonical text of a valid value; throws InputError otherwise.
std::string canonicalValue(const ParameterSpec& spec, const std::string& text,
                           std::string_view owner) {
  auto bad = [&](const std::string& why) {
    const std::string_view type = typeName(spec.type);
    const char* article = type.front() == 'i' ? "an" : "a";  // an integer, a number
    return InputError(fmt::format("{} parameter '{}' = '{}' {}; give {} {} in {}", owner, spec.name,
                                  text, why, article, type, rangeText(spec)));
  };
  switch (spec.type) {
    case ParameterType::kChoice:
    case ParameterType::kBoolean:
    case ParameterType::kIntegerChoice:
      for (const std::string& c : spec.choices)
        if (c == text) return text;
      throw bad("is not one of the choices");
    case ParameterType::kText:
      if (text.empty()) throw bad("is empty");
      return text;
    case ParameterType::kInteger: {
      double v = 0;
      if (!parseDouble(text, v) || v != std::floor(v)) throw bad("is not an integer");
      if (v < spec.min || v > spec.max) throw bad("is out of range");
      return fmt::format("{}", static_cast<long long>(v));
    }
    case ParameterType::kNumber: {
      double v = 0;
      if (!parseDouble(text, v)) throw bad("is not a number");
      if (v < spec.min || v > spec.max) throw bad("is out of range");
      return fmt::format("{}", v);
    }
    case ParameterType::kVector3: {
      std::vector<std::string> parts;
      std::size_t start = 0;
      for (std::size_t comma; (comma = text.find(',', start)) != std::string::npos;
           start = comma + 1)
        parts.push_back(text.substr(start, comma - start));
      parts.push_back(text.substr(start));
      if (parts.size() != 3) throw bad("does not have three components");
      std::string canonical;
      for (const std::string& p : parts) {
        double v = 0;
        if (!parseDouble(p, v)) throw bad("has a component that is not a number");
        if (v < spec.min || v > spec.max) throw bad("has a component out of range");
        if (!canonical.empty()) canonical += ',';
        canonical += fmt::format("{}", v);
      }
      return canonical;
    }
  }
  throw std::logic_error("unknown parameter type");
}

}  // namespace

ParameterSpec numericParameter(std::string name, ParameterType type, std::string default_value,
                               double min, double max, std::string unit, std::string doc) {
  ParameterSpec spec;
  spec.name = std::move(name);
  spec.type = type;
  spec.default_value = std::move(default_value);
  spec.min = min;
  spec.max = max;
  spec.unit = std::move(unit);
  spec.doc = std::move(doc);
  return spec;
}

ParameterSpec choiceParameter(std::string name, std::string default_value,
                              std::vector<std::string> choices, std::string doc) {
  ParameterSpec spec;
  spec.name = std::move(name);
  spec.type = ParameterType::kChoice;
  spec.default_value = std::move(default_value);
  spec.choices = std::move(choices);
  spec.doc = std::move(doc);
  return spec;
}

ParameterSpec textParameter(std::string name, std::string default_value, std::string doc) {
  ParameterSpec spec;
  spec.name = std::move(name);
  spec.type = ParameterType::kText;
  spec.default_value = std::move(default_value);
  spec.doc = std::move(doc);
  return spec;
}

ParameterSpec booleanParameter(std::string name, bool default_value, std::string doc) {
  ParameterSpec spec = choiceParameter(std::move(name), default_value ? "true" : "false",
                                       {"true", "false"}, std::move(doc));
  spec.type = ParameterType::kBoolean;
  return spec;
}

ParameterSpec integerChoiceParameter(std::string name, int default_value, std::vector<int> choices,
                                     std::string unit, std::string doc) {
  std::vector<std::string> texts;
  for (int choice : choices) texts.push_back(std::to_string(choice));
  ParameterSpec spec = choiceParameter(std::move(name), std::to_string(default_value),
                                       std::move(texts), std::move(doc));
  spec.type = ParameterType::kIntegerChoice;
  spec.unit = std::move(unit);
  return spec;
}

ParameterTable joinParameterTables(std::initializer_list<ParameterTable> parts) {
  ParameterTable table;
  for (const ParameterTable& part : parts)
    for (const ParameterSpec& spec : part) {
      for (const ParameterSpec& earlier : table)
        if (earlier.name == spec.name)
          throw std::logic_error(fmt::format("parameter '{}' is declared twice", spec.name));
      table.push_back(spec);
    }
  return table;
}

const std::string& ParameterValues::find(std::string_view name,
                                         std::initializer_list<ParameterType> types) const {
  for (std::size_t i = 0; i < values_.size(); ++i) {
    if (values_[i].first != name) continue;
    if (types.size() > 0 && std::find(types.begin(), types.end(), types_[i]) == types.end())
      throw std::logic_error(
          fmt::format("parameter '{}' is a {}, read as another type", name, typeName(types_[i])));
    return values_[i].second;
  }
  throw std::logic_error(fmt::format("parameter '{}' is not declared", name));
}

const std::string& ParameterValues::text(std::string_view name) const {
  return find(name, {});
}

double ParameterValues::number(std::string_view name) const {
  return std::stod(find(name, {ParameterType::kNumber, ParameterType::kInteger}));
}

int ParameterValues::integer(std::string_view name) const {
  return std::stoi(find(name, {ParameterType::kInteger, ParameterType::kIntegerChoice}));
}

bool ParameterValues::boolean(std::string_view name) const {
  return find(name, {ParameterType::kBoolean}) == "true";
}

std::vector<double> ParameterValues::vector3(std::string_view name) const {
  const std::string& text = find(name, {ParameterType::kVector3});
  std::vector<double> v;
  std::size_t start = 0;
  for (int i = 0; i < 3; ++i) {
    std::size_t comma = text.find(',', start);
    v.push_back(std::stod(text.substr(start, comma - start)));
    start = comma + 1;
  }
  return v;
}

std::vector<std::pair<std::string, std::string>> ParameterValues::canonical() const {
  return values_;
}

ParameterValues parseParameters(const ParameterTable& table,
                                const std::vector<std::string>& assignments,
                                std::string_view owner) {
  std::map<std::string, std::string> given;
  for (const std::string& assignment : assignments) {
    const std::size_t eq = assignment.find('=');
    if (eq == std::string::npos || eq == 0)
      throw InputError(fmt::format("'{}' is not a key=value assignment for {}", assignment, owner));
    const std::string key = assignment.substr(0, eq);
    const ParameterSpec* spec = nullptr;
    for (const ParameterSpec& s : table)
      if (s.name == key) spec = &s;
    if (!spec) {
      const std::string known =
          joinNames(table, ", ", [](const ParameterSpec& s) { return s.name; });
      throw InputError(
          fmt::format("{} has no parameter '{}'; {}", owner, key,
                      known.empty() ? "it takes none" : "its parameters are " + known));
    }
    if (given.count(key))
      throw InputError(fmt::format("{} parameter '{}' is given twice; give it once", owner, key));
    given[key] = canonicalValue(*spec, assignment.substr(eq + 1), owner);
  }
  ParameterValues values;
  for (const ParameterSpec& spec : table) {
    auto it = given.find(spec.name);
    values.values_.emplace_back(spec.name, it != given.end()
                                               ? it->second
                                               : canonicalValue(spec, spec.default_value, owner));
    values.types_.push_back(spec.type);
  }
  return values;
}

std::string parameterMarkdownTable(const ParameterTable& table) {
  std::string out = "| parameter | type | default | range | meaning |\n|---|---|---|---|---|\n";
  for (const ParameterSpec& s : table) {
    // fmt rather than "`" + …: GCC 12's -Wrestrict misfires on operator+(const char*, string&&).
    const std::string range = hasChoices(s.type)
                                  ? fmt::format("`{}`{}{}", joinNames(s.choices, "`, `"),
                                                s.unit.empty() ? "" : " ", s.unit)
                                  : rangeText(s);
    out += fmt::format("| `{}` | {} | `{}` | {} | {} |\n", s.name, typeName(s.type),
                       s.default_value, range, s.doc);
  }
  return out;
}

std::vector<std::string> describeParameters(const ParameterTable& table) {
  std::vector<std::string> lines;
  for (const ParameterSpec& s : table)
    lines.push_back(fmt::format("{} ({}, default {}, {}): {}", s.name, typeName(s.type),
                                s.default_value, rangeText(s), s.doc));
  return lines;
}

}  // namespace gib
