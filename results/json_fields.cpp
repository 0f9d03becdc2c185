#include "results/json_fields.h"

#include "common/input_error.h"

#include <fmt/format.h>

#include <limits>

namespace gib::results::detail {

JsonField::JsonField(const nlohmann::ordered_json& value, std::string_view source,
                     std::string_view fix)
    : value_(&value), source_(source), fix_(fix) {}

JsonField::JsonField(const nlohmann::ordered_json& value, const JsonField& parent,
                     std::string_view key, std::size_t index)
    : value_(&value),
      source_(parent.source_),
      fix_(parent.fix_),
      parent_(&parent),
      key_(key),
      index_(index) {}

std::string JsonField::path() const {
  if (!parent_) return {};
  const std::string path = parent_->path();
  if (key_.empty()) return fmt::format("{}[{}]", path, index_);
  return path.empty() ? std::string(key_) : fmt::format("{}.{}", path, key_);
}

void JsonField::fail(const std::string& problem) const {
  const std::string path = this->path();
  throw InputError(
      fmt::format("{}: {}: {}; {}", source_, path.empty() ? "top level" : path, problem, fix_));
}

namespace {

std::string describeType(const nlohmann::ordered_json& value) {
  if (value.is_null()) return "null";
  if (value.is_object()) return "an object";
  if (value.is_array()) return "an array";
  if (value.is_string()) return "a string";
  if (value.is_boolean()) return "a boolean";
  return "a number";
}

}  // namespace

void JsonField::expect(bool ok, const char* expected) const {
  if (!ok) fail(fmt::format("expected {}, found {}", expected, describeType(*value_)));
}

JsonField JsonField::at(const char* key) const {
  expect(value_->is_object(), "an object");
  auto it = value_->find(key);
  if (it == value_->end()) JsonField(*value_, *this, key, 0).fail("missing");
  return JsonField(*it, *this, key, 0);
}

bool JsonField::has(const char* key) const {
  expect(value_->is_object(), "an object");
  auto it = value_->find(key);
  return it != value_->end() && !it->is_null();
}

std::optional<JsonField> JsonField::find(const char* key) const {
  if (!has(key)) return std::nullopt;
  return at(key);
}

std::string JsonField::asString() const {
  expect(value_->is_string(), "a string");
  return value_->get<std::string>();
}

double JsonField::asNumber() const {
  if (value_->is_number()) return value_->get<double>();
  if (value_->is_string()) {
    const std::string& text = value_->get_ref<const std::string&>();
    if (text == "nan") return std::numeric_limits<double>::quiet_NaN();
    if (text == "inf") return std::numeric_limits<double>::infinity();
    if (text == "-inf") return -std::numeric_limits<double>::infinity();
  }
  fail(fmt::format("expected a number (or \"nan\", \"inf\", \"-inf\"), found {}",
                   value_->is_string() ? fmt::format("\"{}\"", value_->get<std::string>())
                                       : describeType(*value_)));
}

int JsonField::asInt() const {
  const bool fits = value_->is_number_integer() &&
                    value_->get<long long>() >= std::numeric_limits<int>::min() &&
                    value_->get<long long>() <= std::numeric_limits<int>::max();
  expect(fits, "an integer");
  return value_->get<int>();
}

unsigned long long JsonField::asUnsigned() const {
  expect(value_->is_number_unsigned(), "a non-negative integer");
  return value_->get<unsigned long long>();
}

bool JsonField::asBool() const {
  expect(value_->is_boolean(), "true or false");
  return value_->get<bool>();
}

void JsonField::forEachElement(const std::function<void(const JsonField&)>& visit) const {
  expect(value_->is_array(), "an array");
  std::size_t index = 0;
  for (const auto& element : *value_) visit(JsonField(element, *this, {}, index++));
}

void JsonField::forEachMember(
    const std::function<void(const std::string& name, const JsonField&)>& visit) const {
  expect(value_->is_object(), "an object");
  for (const auto& [name, member] : value_->items()) visit(name, JsonField(member, *this, name, 0));
}

}  // namespace gib::results::detail
