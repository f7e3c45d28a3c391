// Formats stage: JSON values as GeoJSON property values (see json_properties.hpp).
#include "formats/json_properties.hpp"

#include <string>

namespace casteljau::json {

PropertyValue to_property(simdjson::dom::element e) {
    PropertyValue v;
    switch (e.type()) {
        case simdjson::dom::element_type::NULL_VALUE: break;
        case simdjson::dom::element_type::BOOL:
            v.type = PropertyValue::Type::Bool;
            v.number = e.get_bool().value_unsafe() ? 1 : 0;
            break;
        case simdjson::dom::element_type::INT64:
        case simdjson::dom::element_type::UINT64:
        case simdjson::dom::element_type::DOUBLE:
            v.type = PropertyValue::Type::Number;
            v.number = e.get_double().value_unsafe();
            break;
        case simdjson::dom::element_type::STRING:
            v.type = PropertyValue::Type::String;
            v.text = std::string(e.get_string().value_unsafe());
            break;
        default:
            v.type = PropertyValue::Type::Json;
            v.text = simdjson::minify(e);
            break;
    }
    return v;
}

std::vector<std::pair<std::string, PropertyValue>> to_properties(simdjson::dom::element e, JsonPath& path) {
    std::vector<std::pair<std::string, PropertyValue>> out;
    if (e.is_null()) return out;
    simdjson::dom::object obj;
    if (e.get_object().get(obj) != simdjson::SUCCESS)
        path.fail(ErrorKind::Parse, "\"properties\" must be an object or null");
    for (auto field : obj) out.emplace_back(std::string(field.key), to_property(field.value));
    return out;
}

std::string id_text(simdjson::dom::element e) {
    const PropertyValue v = to_property(e);
    return v.type == PropertyValue::Type::Null ? std::string() : v.to_string();
}

}  // namespace casteljau::json
