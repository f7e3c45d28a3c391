// JSON stage: helpers shared by the JSON readers (see json_support.hpp).
#include "json/json_support.hpp"

#include <string>
#include <utility>
#include <cctype>

namespace casteljau::json {

namespace {

bool is_ws(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

}  // namespace

namespace {

// A validating scan of RFC 8259 JSON with an explicit stack (no recursion). Each step returns
// whether the text can go on; `i` is then the offending byte.
class SyntaxScan {
public:
    explicit SyntaxScan(std::string_view s) : s_(s), n_(s.size()) {}

    // The offset of the first byte that cannot continue a valid document (npos: none).
    std::size_t run() {
        for (;;) {  // expecting a value at i_
            skip_ws();
            if (i_ >= n_) return n_;
            bool value_done = false;
            if (s_[i_] == '{' || s_[i_] == '[') {
                if (const std::size_t bad = open_container(value_done); bad != kNoError) return bad;
            } else {
                if (!scalar()) return i_ >= n_ ? n_ : i_;
                value_done = true;
            }
            if (value_done)
                if (const std::size_t bad = after_value(); bad != kGoOn) return bad;
        }
    }

private:
    static constexpr std::size_t kNoError = std::string_view::npos;
    static constexpr std::size_t kGoOn = std::string_view::npos - 1;  // a value is expected next

    void skip_ws() {
        while (i_ < n_ && is_ws(s_[i_])) ++i_;
    }
    bool digit() const { return i_ < n_ && std::isdigit(static_cast<unsigned char>(s_[i_])); }

    bool string() {
        ++i_;
        while (i_ < n_) {
            const unsigned char ch = static_cast<unsigned char>(s_[i_]);
            if (ch == '"') {
                ++i_;
                return true;
            }
            if (ch < 0x20) return false;
            if (ch == '\\') {
                ++i_;
                if (i_ >= n_) return false;
                const char e = s_[i_];
                if (e == 'u') {
                    for (int k = 0; k < 4; ++k) {
                        ++i_;
                        if (i_ >= n_ || !std::isxdigit(static_cast<unsigned char>(s_[i_]))) return false;
                    }
                } else if (std::string_view("\"\\/bfnrt").find(e) == std::string_view::npos) {
                    return false;
                }
            }
            ++i_;
        }
        return false;
    }

    bool literal(std::string_view lit) {
        for (char l : lit) {
            if (i_ >= n_ || s_[i_] != l) return false;
            ++i_;
        }
        return true;
    }

    bool number() {
        if (s_[i_] == '-') ++i_;
        if (!digit()) return false;
        if (s_[i_] == '0')
            ++i_;
        else
            while (digit()) ++i_;
        if (i_ < n_ && s_[i_] == '.') {
            ++i_;
            if (!digit()) return false;
            while (digit()) ++i_;
        }
        if (i_ < n_ && (s_[i_] == 'e' || s_[i_] == 'E')) {
            ++i_;
            if (i_ < n_ && (s_[i_] == '+' || s_[i_] == '-')) ++i_;
            if (!digit()) return false;
            while (digit()) ++i_;
        }
        return true;
    }

    // One scalar at i.
    bool scalar() {
        if (i_ >= n_) return false;
        const char c = s_[i_];
        if (c == '"') return string();
        for (std::string_view lit : {std::string_view("true"), std::string_view("false"), std::string_view("null")})
            if (c == lit[0]) return literal(lit);
        if (c == '-' || (c >= '0' && c <= '9')) return number();
        return false;
    }

    // An object member's key and colon at i (after '{' or ','): kNoError when both are there,
    // otherwise where the text goes wrong.
    std::size_t member_key() {
        skip_ws();
        if (i_ >= n_) return n_;
        if (s_[i_] != '"' || !scalar()) return i_;
        skip_ws();
        if (i_ >= n_) return n_;
        if (s_[i_] != ':') return i_;
        ++i_;
        return kNoError;
    }

    // '{' or '[' at i: an empty container is a whole value (value_done); else its first member's
    // key or first element comes next.
    std::size_t open_container(bool& value_done) {
        const char open = s_[i_];
        stack_.push_back(open);
        ++i_;
        skip_ws();
        if (i_ < n_ && s_[i_] == (open == '{' ? '}' : ']')) {
            ++i_;
            stack_.pop_back();
            value_done = true;
            return kNoError;
        }
        return open == '{' ? member_key() : kNoError;
    }

    // After a value: closes containers or moves to the next element (kGoOn: a value comes next).
    std::size_t after_value() {
        for (;;) {
            skip_ws();
            if (stack_.empty()) return i_ < n_ ? i_ : kNoError;  // trailing content, or valid
            if (i_ >= n_) return n_;
            const char top = stack_.back();
            if (s_[i_] == ',') {
                ++i_;
                if (top == '{')
                    if (const std::size_t bad = member_key(); bad != kNoError) return bad;
                return kGoOn;
            }
            if (!((top == '{' && s_[i_] == '}') || (top == '[' && s_[i_] == ']'))) return i_;
            ++i_;
            stack_.pop_back();
        }
    }

    std::string_view s_;
    std::size_t n_, i_ = 0;
    std::vector<char> stack_;  // '{' or '['
};

}  // namespace

std::size_t syntax_error_offset(std::string_view s) { return SyntaxScan(s).run(); }

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
