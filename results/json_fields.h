// Private to gib_results: strict reading of the JSON files gibench writes (results.json, job
// files), so that a truncated or hand-edited file is one clear error naming the field
// ("<source>: jobs[2].metrics.relmse: expected a number, found a string; <fix>") instead of a
// silently wrong diff. Numbers may be non-finite (results/json_number.h).
#pragma once

#include <nlohmann/json.hpp>

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>

namespace gib::results::detail {

// One value inside a document being read, with where it is, for the error messages. A field
// refers to the field it was read from (the path is only spelled out for an error, so reading a
// good file allocates nothing for it): read depth first, as a recursive reader does, and do not
// keep a field beyond its parent.
class JsonField {
 public:
  // `fix` ends every error message: what the user can do about a bad file. The document,
  // `source` and `fix` must outlive every field read from it.
  JsonField(const nlohmann::ordered_json& value, std::string_view source, std::string_view fix);
  // A temporary document or source would dangle.
  JsonField(nlohmann::ordered_json&&, std::string_view, std::string_view) = delete;
  template <typename Source>
  requires std::is_same_v<Source, std::string> JsonField(const nlohmann::ordered_json&, Source&&,
                                                         std::string_view)
  = delete;

  // A required member of this object: a gib::InputError when this is not an object or the member
  // is missing.
  JsonField at(const char* key) const;
  // An optional member: nullopt when absent or null.
  std::optional<JsonField> find(const char* key) const;
  bool has(const char* key) const;

  std::string asString() const;
  double asNumber() const;  // a number, or "nan", "inf", "-inf" (results/json_number.h)
  int asInt() const;
  unsigned long long asUnsigned() const;
  bool asBool() const;

  // Calls `visit` for each element of this array, or each member of this object in file order.
  void forEachElement(const std::function<void(const JsonField&)>& visit) const;
  void forEachMember(
      const std::function<void(const std::string& name, const JsonField&)>& visit) const;

  const nlohmann::ordered_json& json() const { return *value_; }
  std::string path() const;  // "jobs[2].metrics.relmse"; empty at the top level
  std::string_view source() const { return source_; }
  [[noreturn]] void fail(const std::string& problem) const;

 private:
  JsonField(const nlohmann::ordered_json& value, const JsonField& parent, std::string_view key,
            std::size_t index);
  void expect(bool ok, const char* expected) const;

  const nlohmann::ordered_json* value_;
  std::string_view source_, fix_;
  const JsonField* parent_ = nullptr;  // null at the top level
  std::string_view key_;               // the member name; empty for an array element
  std::size_t index_ = 0;              // the array index when key_ is empty
};

}  // namespace gib::results::detail
