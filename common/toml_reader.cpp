#include "common/toml_reader.h"

#include "common/input_error.h"
#include "common/join.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace gib {

std::string TomlErrorReporter::position(const toml::source_region& at) const {
  const auto line = std::max<toml::source_index>(at.begin.line, 1);
  const auto column = std::max<toml::source_index>(at.begin.column, 1);
  return fmt::format("{}:{}:{}", file_, line, column);
}

void TomlErrorReporter::fail(const toml::source_region& at, std::string_view problem,
                             std::string_view fix) const {
  throw InputError(fmt::format("{}: {}; {}", position(at), problem, fix));
}

void TomlErrorReporter::failWith(const toml::source_region& at, std::string_view message) const {
  throw InputError(fmt::format("{}: {}", position(at), message));
}

toml::table parseTomlFile(const TomlErrorReporter& errors, const std::filesystem::path& path,
                          std::string_view kind) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw InputError(fmt::format("{}: {} not found; check the path", errors.file(), kind));
  try {
    return toml::parse_file(path.string());
  } catch (const toml::parse_error& e) {
    errors.fail(e.source(), fmt::format("invalid TOML: {}", oneLine(std::string(e.description()))),
                "fix the TOML syntax at this position");
  }
}

double tomlNumber(const toml::node& node) {
  if (const auto* i = node.as_integer()) return static_cast<double>(i->get());
  if (const auto* f = node.as_floating_point()) return f->get();
  return NAN;
}

std::string oneLine(std::string text) {
  std::replace(text.begin(), text.end(), '\n', ' ');
  while (!text.empty() && text.back() == ' ') text.pop_back();
  return text;
}

std::string joinKeys(const std::vector<std::string>& keys) {
  return joinNames(keys, ", ");
}

std::vector<std::pair<const toml::key*, const toml::node*>> entriesInFileOrder(
    const toml::table& table) {
  std::vector<std::pair<const toml::key*, const toml::node*>> entries;
  for (auto&& [key, value] : table) entries.emplace_back(&key, &value);
  std::stable_sort(entries.begin(), entries.end(), [](const auto& a, const auto& b) {
    const auto& pa = a.first->source().begin;
    const auto& pb = b.first->source().begin;
    return std::pair(pa.line, pa.column) < std::pair(pb.line, pb.column);
  });
  return entries;
}

TomlTableReader::TomlTableReader(const TomlErrorReporter& errors, const toml::table& table,
                                 std::string name, std::string header,
                                 std::vector<std::string> allowed)
    : errors_(errors), table_(table), name_(std::move(name)), header_(std::move(header)) {
  for (auto&& [key, node] : table) {
    if (std::find(allowed.begin(), allowed.end(), key.str()) == allowed.end())
      errors_.fail(key.source(), fmt::format("unknown key '{}' in {}", key.str(), header_),
                   fmt::format("allowed keys: {}", joinKeys(allowed)));
  }
}

std::string TomlTableReader::path(std::string_view key) const {
  return name_.empty() ? std::string(key) : fmt::format("{}.{}", name_, key);
}

const toml::node& TomlTableReader::require(std::string_view key, std::string_view example) const {
  const toml::node* node = find(key);
  if (!node)
    errors_.fail(table_, fmt::format("missing key '{}'", path(key)),
                 fmt::format("add {} = {} to {}", key, example, header_));
  return *node;
}

double TomlTableReader::number(const toml::node& node, std::string_view key) const {
  const double value = tomlNumber(node);
  if (!std::isfinite(value))
    errors_.fail(node, fmt::format("{} must be a finite number", path(key)),
                 "write a number such as 1.0");
  return value;
}

long long TomlTableReader::integer(const toml::node& node, std::string_view key, long long min,
                                   long long max, std::string_view example) const {
  const auto* value = node.as_integer();
  if (!value || value->get() < min || value->get() > max)
    errors_.fail(node, fmt::format("{} must be an integer in [{}, {}]", path(key), min, max),
                 fmt::format("write e.g. {} = {}", key, example));
  return value->get();
}

std::string TomlTableReader::string(const toml::node& node, std::string_view key) const {
  const auto* s = node.as_string();
  if (!s || s->get().empty())
    errors_.fail(node, fmt::format("{} must be a non-empty string", path(key)),
                 "write it in double quotes, e.g. \"name\"");
  return s->get();
}

bool TomlTableReader::boolean(const toml::node& node, std::string_view key) const {
  const auto* b = node.as_boolean();
  if (!b)
    errors_.fail(node, fmt::format("{} must be true or false", path(key)),
                 "write true or false without quotes");
  return b->get();
}

const toml::table& requireTomlTable(const TomlErrorReporter& errors, const toml::node& node,
                                    const std::string& name, std::string_view fix) {
  if (!node.is_table()) errors.fail(node, fmt::format("{} must be a table", name), fix);
  return *node.as_table();
}

std::vector<const toml::table*> tomlTableArray(const TomlTableReader& root, std::string_view key) {
  std::vector<const toml::table*> tables;
  const toml::node* node = root.find(key);
  if (!node) return tables;
  const toml::array* array = node->as_array();
  if (!array || (!array->empty() && !array->is_array_of_tables()))
    root.errors().fail(*node, fmt::format("{} must be an array of tables", key),
                       fmt::format("write each entry as a [[{}]] table", key));
  for (const toml::node& item : *array) tables.push_back(item.as_table());
  return tables;
}

}  // namespace gib
