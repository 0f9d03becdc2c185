// Private to gib_reports: a struct's plain members named once, so that writing and strict reading
// of results.json (results_json.cpp) share one list and cannot disagree on a name or a type.
#pragma once

#include "results/json_fields.h"
#include "results/json_number.h"

#include <nlohmann/json.hpp>

#include <array>
#include <string>
#include <type_traits>

namespace gib::results::detail {

template <typename Struct>
struct JsonMember {
  const char* name;
  void (*write)(const Struct& object, nlohmann::ordered_json& value);
  void (*read)(const JsonField& value, Struct& object);
};

template <typename MemberPointer>
struct MemberTraits;
template <typename Struct, typename Type>
struct MemberTraits<Type Struct::*> {
  using StructType = Struct;
  using ValueType = Type;
};

// One entry of a table: jsonMember<&RunInfo::id>("id"). Members are strings, booleans, ints,
// unsigned 64-bit integers or doubles (which may be non-finite: results/json_number.h).
template <auto Pointer>
JsonMember<typename MemberTraits<decltype(Pointer)>::StructType> jsonMember(const char* name) {
  using Struct = typename MemberTraits<decltype(Pointer)>::StructType;
  using Type = typename MemberTraits<decltype(Pointer)>::ValueType;
  auto write = [](const Struct& object, nlohmann::ordered_json& value) {
    if constexpr (std::is_same_v<Type, double>)
      value = numberToJson(object.*Pointer);
    else
      value = object.*Pointer;
  };
  auto read = [](const JsonField& value, Struct& object) {
    if constexpr (std::is_same_v<Type, std::string>)
      object.*Pointer = value.asString();
    else if constexpr (std::is_same_v<Type, bool>)
      object.*Pointer = value.asBool();
    else if constexpr (std::is_same_v<Type, int>)
      object.*Pointer = value.asInt();
    else if constexpr (std::is_same_v<Type, unsigned long long>)
      object.*Pointer = value.asUnsigned();
    else if constexpr (std::is_same_v<Type, double>)
      object.*Pointer = value.asNumber();
    else
      static_assert(sizeof(Type) == 0, "no JSON reading for this member type");
  };
  return {name, write, read};
}

template <typename Struct, std::size_t N>
void writeMembers(const Struct& object, const std::array<JsonMember<Struct>, N>& members,
                  nlohmann::ordered_json& out) {
  for (const JsonMember<Struct>& m : members) m.write(object, out[m.name]);
}

// Every member is required: a missing or mistyped one is a gib::InputError naming it.
template <typename Struct, std::size_t N>
void readMembers(const JsonField& field, const std::array<JsonMember<Struct>, N>& members,
                 Struct& object) {
  for (const JsonMember<Struct>& m : members) m.read(field.at(m.name), object);
}

}  // namespace gib::results::detail
