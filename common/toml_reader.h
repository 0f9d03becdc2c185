// Reading the project's TOML input files (scene files, suite files) with one error style: every
// problem throws gib::InputError with one line "<file>:<line>:<column>: <problem>; <fix>", the
// position being that of the offending key or value, or of the table that lacks a key. An unknown
// key is an error that lists the allowed ones, so a mistyped key is never silently ignored.
#pragma once

#include <toml++/toml.h>

#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace gib {

// Formats and throws the errors of one file.
class TomlErrorReporter {
 public:
  explicit TomlErrorReporter(std::string file) : file_(std::move(file)) {}

  [[noreturn]] void fail(const toml::source_region& at, std::string_view problem,
                         std::string_view fix) const;
  [[noreturn]] void fail(const toml::node& at, std::string_view problem,
                         std::string_view fix) const {
    fail(at.source(), problem, fix);
  }
  // Places a message that already reads "<problem>; <fix>" (an InputError from another layer,
  // such as an unknown technique) at `at`.
  [[noreturn]] void failWith(const toml::source_region& at, std::string_view message) const;

  // "<file>:<line>:<column>"; nodes toml++ makes up (the implicit `materials` of
  // [materials.white]) have no position and read as line 1, column 1.
  std::string position(const toml::source_region& at) const;
  const std::string& file() const { return file_; }

 private:
  std::string file_;
};

// Parses `path`. Throws "<file>: <kind> not found; check the path" for a missing file and a
// positioned error for invalid TOML. `kind` names the file for the user: "scene file".
toml::table parseTomlFile(const TomlErrorReporter& errors, const std::filesystem::path& path,
                          std::string_view kind);

// The value of an integer or floating-point node; NaN for anything else.
double tomlNumber(const toml::node& node);

// The text with line breaks turned into spaces and trailing spaces removed (toml++'s and
// tinyobjloader's messages span lines; ours are one line).
std::string oneLine(std::string text);

// "a, b, c".
std::string joinKeys(const std::vector<std::string>& keys);

// The entries of a table in the order of the file (toml++ keeps a table's keys sorted).
std::vector<std::pair<const toml::key*, const toml::node*>> entriesInFileOrder(
    const toml::table& table);

// One TOML table with the keys it may hold. Rejects unknown keys up front, so that a mistyped
// key is reported as such rather than as a missing required key (pbrt's ReportUnused habit).
class TomlTableReader {
 public:
  // `name`: the dotted prefix of its keys in messages ("camera"; "" for the root); `header`: how
  // the file spells the table ("[camera]", "[[meshes]] entry 2").
  TomlTableReader(const TomlErrorReporter& errors, const toml::table& table, std::string name,
                  std::string header, std::vector<std::string> allowed);

  // The dotted name of a key, as error messages show it: "camera.position".
  std::string path(std::string_view key) const;
  const toml::table& table() const { return table_; }
  const TomlErrorReporter& errors() const { return errors_; }
  const std::string& header() const { return header_; }

  const toml::node* find(std::string_view key) const { return table_.get(key); }
  // The node of a required key; `example` is a value shown in the fix ("[x, y, z]").
  const toml::node& require(std::string_view key, std::string_view example) const;

  // A finite number (integer or float).
  double number(const toml::node& node, std::string_view key) const;
  // An integer in [min, max]; `example` is a value shown in the fix.
  long long integer(const toml::node& node, std::string_view key, long long min, long long max,
                    std::string_view example) const;
  // A non-empty string.
  std::string string(const toml::node& node, std::string_view key) const;
  // true or false.
  bool boolean(const toml::node& node, std::string_view key) const;

 private:
  const TomlErrorReporter& errors_;
  const toml::table& table_;
  std::string name_;
  std::string header_;
};

// `node` as a table, or an error "<name> must be a table; <fix>".
const toml::table& requireTomlTable(const TomlErrorReporter& errors, const toml::node& node,
                                    const std::string& name, std::string_view fix);

// The items of an array of tables ([[meshes]]); empty when the key is absent.
std::vector<const toml::table*> tomlTableArray(const TomlTableReader& root, std::string_view key);

}  // namespace gib
