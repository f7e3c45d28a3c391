// Formats stage, internal (also read by the map stage's style reader): JSON values as the
// property values of map features (PropertyValue, include/casteljau/geojson.hpp).
#pragma once

#include <simdjson.h>

#include <string>
#include <utility>
#include <vector>

#include "casteljau/geojson.hpp"
#include "json/json_support.hpp"

namespace casteljau::json {

// null, a boolean, a number or a string as itself; an array or object as its minified text.
PropertyValue to_property(simdjson::dom::element e);
// The members of a "properties" object (empty for null), in document order. Fails through `path`
// with Error(Parse) for anything else.
std::vector<std::pair<std::string, PropertyValue>> to_properties(simdjson::dom::element e, JsonPath& path);
// A feature's "id" as text: a string as itself, a number as its shortest round-trip text.
std::string id_text(simdjson::dom::element e);

}  // namespace casteljau::json
