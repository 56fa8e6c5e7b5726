// A JSON object's member by key, or null where it has none: how the readers of JSON room files (Quest captures,
// MRUK rooms) look members up, telling a missing member from one of the wrong type.
#pragma once
#include <nlohmann/json.hpp>

namespace roomsense::scanio {

inline const nlohmann::json* member(const nlohmann::json& object, const char* key) {
  const auto it = object.find(key);
  return it == object.end() ? nullptr : &*it;
}

}  // namespace roomsense::scanio
