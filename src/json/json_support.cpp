// JSON stage: helpers shared by the JSON readers (see json_support.hpp).
#include "json/json_support.hpp"

#include <string>
#include <utility>
#include <cctype>

namespace casteljau::json {

namespace {

bool is_ws(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

}  // namespace

// A validating scan of RFC 8259 JSON with an explicit stack (no recursion), returning the offset of
// the first byte that cannot continue a valid document.
std::size_t syntax_error_offset(std::string_view s) {
    std::size_t i = 0;
    const std::size_t n = s.size();
    std::vector<char> stack;  // '{' or '['
    auto skip_ws = [&] {
        while (i < n && is_ws(s[i])) ++i;
    };
    // Scans one scalar at i; returns false at the offending byte.
    auto scalar = [&]() -> bool {
        if (i >= n) return false;
        const char c = s[i];
        if (c == '"') {
            ++i;
            while (i < n) {
                const unsigned char ch = static_cast<unsigned char>(s[i]);
                if (ch == '"') {
                    ++i;
                    return true;
                }
                if (ch < 0x20) return false;
                if (ch == '\\') {
                    ++i;
                    if (i >= n) return false;
                    const char e = s[i];
                    if (e == 'u') {
                        for (int k = 0; k < 4; ++k) {
                            ++i;
                            if (i >= n || !std::isxdigit(static_cast<unsigned char>(s[i]))) return false;
                        }
                    } else if (std::string_view("\"\\/bfnrt").find(e) == std::string_view::npos) {
                        return false;
                    }
                }
                ++i;
            }
            return false;
        }
        for (std::string_view lit : {std::string_view("true"), std::string_view("false"), std::string_view("null")}) {
            if (c == lit[0]) {
                for (char l : lit) {
                    if (i >= n || s[i] != l) return false;
                    ++i;
                }
                return true;
            }
        }
        if (c == '-' || (c >= '0' && c <= '9')) {
            if (s[i] == '-') ++i;
            if (i >= n || !std::isdigit(static_cast<unsigned char>(s[i]))) return false;
            if (s[i] == '0')
                ++i;
            else
                while (i < n && std::isdigit(static_cast<unsigned char>(s[i]))) ++i;
            if (i < n && s[i] == '.') {
                ++i;
                if (i >= n || !std::isdigit(static_cast<unsigned char>(s[i]))) return false;
                while (i < n && std::isdigit(static_cast<unsigned char>(s[i]))) ++i;
            }
            if (i < n && (s[i] == 'e' || s[i] == 'E')) {
                ++i;
                if (i < n && (s[i] == '+' || s[i] == '-')) ++i;
                if (i >= n || !std::isdigit(static_cast<unsigned char>(s[i]))) return false;
                while (i < n && std::isdigit(static_cast<unsigned char>(s[i]))) ++i;
            }
            return true;
        }
        return false;
    };
    // An object member's key and colon at i (after '{' or ','): kNoError when both are there,
    // otherwise where the text goes wrong.
    constexpr std::size_t kNoError = std::string_view::npos;
    auto member_key = [&]() -> std::size_t {
        skip_ws();
        if (i >= n) return n;
        if (s[i] != '"' || !scalar()) return i;
        skip_ws();
        if (i >= n) return n;
        if (s[i] != ':') return i;
        ++i;
        return kNoError;
    };
    // Expecting a value at i.
    for (;;) {
        skip_ws();
        if (i >= n) return n;
        bool value_done = false;
        if (s[i] == '{') {
            stack.push_back('{');
            ++i;
            skip_ws();
            if (i < n && s[i] == '}') {
                ++i;
                stack.pop_back();
                value_done = true;
            } else {
                if (const std::size_t bad = member_key(); bad != kNoError) return bad;
                continue;
            }
        } else if (s[i] == '[') {
            stack.push_back('[');
            ++i;
            skip_ws();
            if (i < n && s[i] == ']') {
                ++i;
                stack.pop_back();
                value_done = true;
            } else
                continue;
        } else {
            if (!scalar()) return i >= n ? n : i;
            value_done = true;
        }
        // After a value: close containers or move to the next element.
        while (value_done) {
            skip_ws();
            if (stack.empty()) return i < n ? i : std::string_view::npos;  // trailing content, or valid
            if (i >= n) return n;
            const char top = stack.back();
            if (s[i] == ',') {
                ++i;
                if (top == '{')
                    if (const std::size_t bad = member_key(); bad != kNoError) return bad;
                value_done = false;
            } else if ((top == '{' && s[i] == '}') || (top == '[' && s[i] == ']')) {
                ++i;
                stack.pop_back();
            } else {
                return i;
            }
        }
    }
}

namespace {

std::size_t skip_ws(std::string_view s, std::size_t i) {
    while (i < s.size() && is_ws(s[i])) ++i;
    return i;
}

// The end of the string whose opening quote is at i, in valid JSON.
std::size_t string_end(std::string_view s, std::size_t i) {
    for (++i; i < s.size(); ++i) {
        if (s[i] == '\\')
            ++i;
        else if (s[i] == '"')
            return i + 1;
    }
    return s.size();
}

// The end of the value starting at i (no leading whitespace), in valid JSON. Iterative, so that
// deep nesting costs no stack.
std::size_t value_end(std::string_view s, std::size_t i) {
    if (i >= s.size()) return s.size();
    if (s[i] == '"') return string_end(s, i);
    if (s[i] != '{' && s[i] != '[') {
        while (i < s.size() && s[i] != ',' && s[i] != '}' && s[i] != ']' && !is_ws(s[i])) ++i;
        return i;
    }
    std::size_t depth = 0;
    while (i < s.size()) {
        const char c = s[i];
        if (c == '"') {
            i = string_end(s, i);
            continue;
        }
        if (c == '{' || c == '[')
            ++depth;
        else if ((c == '}' || c == ']') && --depth == 0)
            return i + 1;
        ++i;
    }
    return s.size();
}

std::string unescaped_key(std::string_view quoted) {
    if (quoted.find('\\') == std::string_view::npos) return std::string(quoted.substr(1, quoted.size() - 2));
    simdjson::dom::parser p;
    std::string_view k;
    if (p.parse(quoted.data(), quoted.size(), true).get_string().get(k) != simdjson::SUCCESS) return {};
    return std::string(k);
}

}  // namespace

std::vector<std::pair<std::string, RawValue>> raw_object_members(std::string_view s) {
    std::vector<std::pair<std::string, RawValue>> out;
    std::size_t i = skip_ws(s, 0);
    if (i >= s.size() || s[i] != '{') return out;
    i = skip_ws(s, i + 1);
    while (i < s.size() && s[i] == '"') {
        const std::size_t key_end = string_end(s, i);
        std::string key = unescaped_key(s.substr(i, key_end - i));
        i = skip_ws(s, key_end) + 1;  // past ':'
        i = skip_ws(s, i);
        const std::size_t v_end = value_end(s, i);
        out.push_back({std::move(key), RawValue{i, v_end}});
        i = skip_ws(s, v_end);
        if (i < s.size() && s[i] == ',') i = skip_ws(s, i + 1);
    }
    return out;
}

std::optional<std::vector<RawValue>> raw_array_elements(std::string_view s, RawValue v) {
    if (v.begin >= v.end || s[v.begin] != '[') return std::nullopt;
    std::vector<RawValue> out;
    std::size_t i = skip_ws(s, v.begin + 1);
    while (i < v.end && s[i] != ']') {
        const std::size_t e = value_end(s, i);
        out.push_back(RawValue{i, e});
        i = skip_ws(s, e);
        if (i < v.end && s[i] == ',') i = skip_ws(s, i + 1);
    }
    return out;
}

simdjson::dom::element parse(simdjson::dom::parser& parser, std::string_view text, const std::string& what) {
    simdjson::dom::element root;
    const auto err = parser.parse(text.data(), text.size(), true).get(root);
    if (err == simdjson::SUCCESS) return root;
    if (err == simdjson::DEPTH_ERROR) throw Error(ErrorKind::Limit, what + ": JSON nesting is too deep");
    if (err == simdjson::MEMALLOC || err == simdjson::CAPACITY)
        throw Error(ErrorKind::Limit, what + ": JSON document too large (" + std::to_string(text.size()) + " bytes)");
    const std::size_t at = syntax_error_offset(text);
    std::string msg = what + ": invalid JSON";
    if (at < text.size())
        msg += " at byte " + std::to_string(at);
    else if (at == text.size())
        msg += " (ends early, at byte " + std::to_string(text.size()) + ")";
    msg += ": ";
    msg += simdjson::error_message(err);
    throw Error(ErrorKind::Parse, msg);
}

std::string JsonPath::str() const {
    std::string s = prefix_;
    for (const Part& p : parts_) {
        if (p.is_key) {
            if (!s.empty() && s.back() != ' ') s += '.';
            s += p.name;
        } else {
            s += '[' + std::to_string(p.index) + ']';
        }
    }
    return s.empty() ? "(root)" : s;
}

void JsonPath::fail(ErrorKind kind, const std::string& what) const { throw Error(kind, str() + ": " + what); }

}  // namespace casteljau::json
