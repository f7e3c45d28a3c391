// Formats stage, SVG: internal DTD entities (xml_input.hpp). The XML parser does not expand the
// general entities a document declares in its internal subset, so this pass replaces their
// references in the text after the DOCTYPE before parsing, as XML 1.0 section 4.4 says: in
// content the replacement text is parsed as markup, in attribute values it is text.
#include <cstddef>
#include <map>
#include <string>
#include <string_view>

#include "casteljau/error.hpp"
#include "casteljau/limits.hpp"
#include "formats/svg/xml_input.hpp"

namespace casteljau::svg {

namespace {

// How deeply entity values may refer to other entities (a reference inside a value inside a
// value ...): real documents use one or two levels; entity bombs need many.
constexpr int kMaxEntityDepth = 4;
constexpr std::size_t kMaxEntities = 1000;

using Entities = std::map<std::string, std::string, std::less<>>;

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

bool is_name_char(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-' ||
           c == '.' || c == ':' || static_cast<unsigned char>(c) >= 0x80;
}

// The general entities declared with a literal value in `subset` (the text between [ and ]).
// Parameter entities (%) and external entities (SYSTEM, PUBLIC) are left out.
Entities read_declarations(std::string_view subset) {
    Entities out;
    for (std::size_t pos = subset.find("<!ENTITY"); pos != std::string_view::npos; pos = subset.find("<!ENTITY", pos)) {
        pos += 8;
        while (pos < subset.size() && is_space(subset[pos])) ++pos;
        if (pos >= subset.size() || subset[pos] == '%') continue;
        const std::size_t name_start = pos;
        while (pos < subset.size() && is_name_char(subset[pos])) ++pos;
        const std::string name(subset.substr(name_start, pos - name_start));
        while (pos < subset.size() && is_space(subset[pos])) ++pos;
        if (name.empty() || pos >= subset.size() || (subset[pos] != '"' && subset[pos] != '\'')) continue;
        const std::size_t close = subset.find(subset[pos], pos + 1);
        if (close == std::string_view::npos) break;
        if (out.size() >= kMaxEntities)
            throw Error(ErrorKind::Limit, "the DTD declares more than " + std::to_string(kMaxEntities) + " entities");
        out.emplace(name, std::string(subset.substr(pos + 1, close - pos - 1)));  // the first declaration wins
        pos = close + 1;
    }
    return out;
}

// Appends the text of entity `name`'s value to `out` with the references to declared entities
// in it expanded; `depth` counts the enclosing entities.
void expand_value(const Entities& entities, const std::string& value, int depth, std::size_t cap, std::string& out) {
    if (depth > kMaxEntityDepth)
        throw Error(ErrorKind::Limit, "DTD entities nested deeper than " + std::to_string(kMaxEntityDepth) +
                                          " levels (a recursive entity or an entity bomb)");
    for (std::size_t i = 0; i < value.size();) {
        if (value[i] == '&') {
            std::size_t end = i + 1;
            while (end < value.size() && is_name_char(value[end])) ++end;
            if (end < value.size() && value[end] == ';' && end > i + 1) {
                const auto it = entities.find(std::string_view(value).substr(i + 1, end - i - 1));
                if (it != entities.end()) {
                    expand_value(entities, it->second, depth + 1, cap, out);
                    i = end + 1;
                    continue;
                }
            }
        }
        out += value[i++];
        if (out.size() > cap)
            throw Error(ErrorKind::Limit, "DTD entities expand the document past " + std::to_string(cap) + " bytes");
    }
}

// `text` with what must not end an attribute value escaped.
std::string escape_attribute(std::string_view text) {
    std::string out;
    for (char c : text) {
        if (c == '"')
            out += "&quot;";
        else if (c == '\'')
            out += "&apos;";
        else if (c == '<')
            out += "&lt;";
        else
            out += c;
    }
    return out;
}

// Copies `body` (the document after its DOCTYPE) to `out`, replacing references to `entities`
// outside comments, CDATA sections and processing instructions.
void expand_body(std::string_view body, const Entities& entities, std::size_t cap, std::string& out) {
    char quote = 0;       // inside an attribute value delimited by this quote
    bool in_tag = false;  // inside a start or end tag
    for (std::size_t i = 0; i < body.size();) {
        const std::string_view rest = body.substr(i);
        if (!in_tag) {
            std::string_view close;
            if (rest.starts_with("<!--")) close = "-->";
            if (rest.starts_with("<![CDATA[")) close = "]]>";
            if (rest.starts_with("<?")) close = "?>";
            if (!close.empty()) {
                const std::size_t end = rest.find(close);
                const std::size_t n = end == std::string_view::npos ? rest.size() : end + close.size();
                out.append(rest.substr(0, n));
                i += n;
                continue;
            }
        }
        const char c = body[i];
        if (c == '&') {
            std::size_t end = i + 1;
            while (end < body.size() && is_name_char(body[end])) ++end;
            if (end < body.size() && body[end] == ';' && end > i + 1) {
                const auto it = entities.find(body.substr(i + 1, end - i - 1));
                if (it != entities.end()) {
                    std::string text;
                    expand_value(entities, it->second, 1, cap, text);
                    out += quote ? escape_attribute(text) : text;
                    if (out.size() > cap)
                        throw Error(ErrorKind::Limit,
                                    "DTD entities expand the document past " + std::to_string(cap) + " bytes");
                    i = end + 1;
                    continue;
                }
            }
        } else if (in_tag && quote == 0 && (c == '"' || c == '\'')) {
            quote = c;
        } else if (quote != 0 && c == quote) {
            quote = 0;
        } else if (c == '<' && quote == 0) {
            in_tag = true;
        } else if (c == '>' && quote == 0) {
            in_tag = false;
        }
        out += c;
        ++i;
    }
}

// Where the internal subset that starts at `from` ends (its ']'): quoted values and comments
// may hold a ']' of their own.
std::size_t subset_end(std::string_view text, std::size_t from) {
    char quote = 0;
    for (std::size_t i = from; i < text.size(); ++i) {
        const char c = text[i];
        if (quote) {
            if (c == quote) quote = 0;
        } else if (text.substr(i).starts_with("<!--")) {
            const std::size_t end = text.find("-->", i + 4);
            if (end == std::string_view::npos) return end;
            i = end + 2;
        } else if (c == '"' || c == '\'') {
            quote = c;
        } else if (c == ']') {
            return i;
        }
    }
    return std::string_view::npos;
}

}  // namespace

std::string expand_entities(std::string_view text) {
    const std::size_t doctype = text.find("<!DOCTYPE");
    if (doctype == std::string_view::npos) return {};
    const std::size_t open = text.find_first_of("[>", doctype);
    if (open == std::string_view::npos || text[open] != '[') return {};
    const std::size_t close = subset_end(text, open + 1);
    const std::size_t end = close == std::string_view::npos ? close : text.find('>', close);
    if (end == std::string_view::npos) return {};
    const Entities entities = read_declarations(text.substr(open + 1, close - open - 1));
    if (entities.empty()) return {};
    std::string out(text.substr(0, end + 1));
    expand_body(text.substr(end + 1), entities, current_limits().svgz_bytes, out);
    return out;
}

}  // namespace casteljau::svg
