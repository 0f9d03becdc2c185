// Private to gib_reports: strict reading of the JSON files gibench writes (results.json, job
// files), so that a truncated or hand-edited file is one clear error naming the field
// ("<source>: jobs[2].metrics.relmse: expected a number, found a string; <fix>") instead of a
// silently wrong diff. Numbers may be non-finite (reports/json_number.h).
#pragma once

#include <nlohmann/json.hpp>

#include <cstddef>
#include <functional>
#include <optional>
#include <string>

namespace gib::reports::detail {

// One value inside a document being read, with where it is, for the error messages.
class JsonField {
 public:
  // `fix` ends every error message: what the user can do about a bad file.
  JsonField(const nlohmann::ordered_json& value, std::string source, std::string fix);

  // A required member of this object: a gib::InputError when this is not an object or the member
  // is missing.
  JsonField at(const char* key) const;
  // An optional member: nullopt when absent or null.
  std::optional<JsonField> find(const char* key) const;
  bool has(const char* key) const;

  std::string asString() const;
  double asNumber() const;  // a number, or "nan", "inf", "-inf" (reports/json_number.h)
  int asInt() const;
  unsigned long long asUnsigned() const;
  bool asBool() const;

  // Calls `visit` for each element of this array, or each member of this object in file order.
  void forEachElement(const std::function<void(const JsonField&)>& visit) const;
  void forEachMember(
      const std::function<void(const std::string& name, const JsonField&)>& visit) const;

  const nlohmann::ordered_json& json() const { return *value_; }
  const std::string& path() const { return path_; }
  const std::string& source() const { return source_; }
  [[noreturn]] void fail(const std::string& problem) const;

 private:
  JsonField(const nlohmann::ordered_json& value, const JsonField& parent, std::string path);
  void expect(bool ok, const char* expected) const;

  const nlohmann::ordered_json* value_;
  std::string source_;
  std::string fix_;
  std::string path_;  // "jobs[2].metrics.relmse"; empty at the top level
};

}  // namespace gib::reports::detail
