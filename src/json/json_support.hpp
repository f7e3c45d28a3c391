// JSON stage (internal, used by the formats and map stages): helpers shared by the JSON readers
// (GeoJSON, TopoJSON, map style files): parsing with simdjson's DOM into an Error that names the
// byte offset of malformed JSON, a scan of large documents piece by piece, and a JSON path for
// messages (`features[12].geometry.coordinates[0][3]`).
#pragma once

#include <simdjson.h>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "casteljau/error.hpp"

namespace casteljau::json {

// Parses `text` (copied into simdjson's padded buffer). Throws Error(Parse) "what: invalid JSON at
// byte N: reason" for malformed text, Error(Limit) for nesting beyond simdjson's
// depth (1024 levels) or a document simdjson cannot hold.
simdjson::dom::element parse(simdjson::dom::parser& parser, std::string_view text, const std::string& what);

// Byte offset of the first syntax error in `text` (text.size() when it ends too early), or
// std::string_view::npos when the text is valid JSON apart from its UTF-8 (which the scan does not
// check), found by a small validating scan with an explicit stack.
std::size_t syntax_error_offset(std::string_view text);

// A value inside JSON text, as the byte range [begin, end) of its text.
struct RawValue {
    std::size_t begin = 0, end = 0;
};

// The members of the top-level object of `valid` (text that syntax_error_offset found valid), each
// with its unescaped key, in document order; empty when the top-level value is not an object.
// Together with raw_array_elements this lets a reader parse a large document one piece at a time
// instead of building simdjson's tape (16 bytes per number) for all of it.
std::vector<std::pair<std::string, RawValue>> raw_object_members(std::string_view valid);

// The elements of the array whose text is valid[v.begin, v.end), or nullopt when it is not an array.
std::optional<std::vector<RawValue>> raw_array_elements(std::string_view valid, RawValue v);

// A JSON path built only when a message needs it: a stack of member names and indices.
class JsonPath {
public:
    struct Scope {
        JsonPath& p;
        ~Scope() { p.parts_.pop_back(); }
    };
    Scope key(std::string_view k) {
        parts_.push_back({std::string(k), 0, true});
        return {*this};
    }
    Scope index(std::size_t i) {
        parts_.push_back({{}, i, false});
        return {*this};
    }
    std::string str() const;
    void set_prefix(std::string p) { prefix_ = std::move(p); }
    [[noreturn]] void fail(ErrorKind kind, const std::string& what) const;

private:
    struct Part {
        std::string name;
        std::size_t index;
        bool is_key;
    };
    std::vector<Part> parts_;
    std::string prefix_;
};

}  // namespace casteljau::json
