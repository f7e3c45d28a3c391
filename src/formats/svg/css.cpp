// Formats stage: the CSS reader for SVG style sheets (see css.hpp). A hand-written scanner over the
// text: comments removed first, then rules are cut at braces (nested braces of at-rules skipped),
// selectors parsed compound by compound; anything unreadable drops only its own selector or
// declaration.
#include "formats/svg/css.hpp"

#include "casteljau/limits.hpp"

#include <algorithm>
#include <cctype>

namespace casteljau::css {

namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f'; }

std::string_view trim(std::string_view s) {
    while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
    while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
    return s;
}

bool ident_char(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || static_cast<unsigned char>(c) >= 0x80;
}

std::string strip_comments(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size();) {
        if (text[i] == '/' && i + 1 < text.size() && text[i + 1] == '*') {
            const std::size_t end = text.find("*/", i + 2);
            if (end == std::string_view::npos) break;
            i = end + 2;
            out += ' ';
        } else {
            out += text[i++];
        }
    }
    return out;
}

// Reads an identifier at s[i]; empty when there is none.
std::string ident(std::string_view s, std::size_t& i) {
    const std::size_t b = i;
    while (i < s.size() && ident_char(s[i])) ++i;
    return std::string(s.substr(b, i - b));
}

// The body of an attribute selector, between [ and ]: a name, then optionally an operator (=, ~=,
// ^=, $=, *=, |=) and a value, quoted or not. False when it is not one.
bool parse_attribute_test(std::string_view body, AttributeTest& a) {
    std::size_t j = 0;
    a.name = ident(body, j);
    if (a.name.empty()) return false;
    body = trim(body.substr(j));
    if (body.empty()) return true;
    if (body[0] == '=') {
        a.op = '=';
        body.remove_prefix(1);
    } else if (body.size() >= 2 && body[1] == '=' &&
               std::string_view("~^$*|").find(body[0]) != std::string_view::npos) {
        a.op = body[0];
        body.remove_prefix(2);
    } else {
        return false;
    }
    body = trim(body);
    if (body.size() >= 2 && (body.front() == '"' || body.front() == '\'') && body.back() == body.front())
        body = body.substr(1, body.size() - 2);
    a.value = std::string(body);
    return true;
}

// The counts a selector's specificity is made of.
struct Specificity {
    int ids = 0, classes = 0, types = 0;
};

// One compound selector at s[i] (a type or *, then #id, .class, [attribute] and :first-child, up
// to white space or >), counted into `sp`. False when it is empty or uses anything unsupported.
bool parse_compound(std::string_view s, std::size_t& i, Compound& c, Specificity& sp) {
    bool any = false;
    if (s[i] == '*') {
        ++i;
        any = true;
    } else if (ident_char(s[i])) {
        c.type = ident(s, i);
        ++sp.types;
        any = true;
    }
    while (i < s.size() && !is_space(s[i]) && s[i] != '>') {
        const char k = s[i++];
        if (k == '#' || k == '.') {
            std::string name = ident(s, i);
            if (name.empty()) return false;
            (k == '#' ? c.ids : c.classes).push_back(std::move(name));
            (k == '#' ? sp.ids : sp.classes)++;
        } else if (k == '[') {
            const std::size_t close = s.find(']', i);
            if (close == std::string_view::npos) return false;
            AttributeTest a;
            if (!parse_attribute_test(trim(s.substr(i, close - i)), a)) return false;
            i = close + 1;
            c.attributes.push_back(std::move(a));
            ++sp.classes;
        } else if (k == ':') {
            if (ident(s, i) != "first-child") return false;
            c.first_child = true;
            ++sp.classes;
        } else {
            return false;
        }
        any = true;
    }
    return any;
}

// Parses one selector (no commas): compounds joined by white space (descendant) or > (child).
// False when it uses anything unsupported.
bool parse_selector(std::string_view s, Selector& out) {
    s = trim(s);
    if (s.empty()) return false;
    std::size_t i = 0;
    char pending = ' ';
    Specificity sp;
    while (i < s.size()) {
        if (out.compounds.size() >= kMaxCompounds) return false;
        Compound c;
        c.combinator = pending;
        if (!parse_compound(s, i, c, sp)) return false;
        out.compounds.push_back(std::move(c));
        while (i < s.size() && is_space(s[i])) ++i;
        pending = ' ';
        if (i < s.size() && s[i] == '>') {
            pending = '>';
            ++i;
            while (i < s.size() && is_space(s[i])) ++i;
            if (i >= s.size()) return false;
        }
    }
    out.specificity = sp.ids * 10000 + std::min(sp.classes, 99) * 100 + std::min(sp.types, 99);
    return !out.compounds.empty();
}

// Whether `word` is one of the white-space separated words of `list`.
bool has_word(std::string_view list, std::string_view word) {
    for (std::size_t i = 0; i < list.size();) {
        while (i < list.size() && is_space(list[i])) ++i;
        std::size_t j = i;
        while (j < list.size() && !is_space(list[j])) ++j;
        if (list.substr(i, j - i) == word) return true;
        i = j;
    }
    return false;
}

bool attribute_matches(const AttributeTest& a, const pugi::xml_node& e) {
    const pugi::xml_attribute attr = e.attribute(a.name.c_str());
    if (!attr) return false;
    const std::string_view v = attr.value();
    const std::string_view w = a.value;
    switch (a.op) {
        case 0: return true;
        case '=': return v == w;
        case '^': return !w.empty() && v.substr(0, w.size()) == w;
        case '$': return !w.empty() && v.size() >= w.size() && v.substr(v.size() - w.size()) == w;
        case '*': return !w.empty() && v.find(w) != std::string_view::npos;
        case '|': return v == w || v.substr(0, w.size() + 1) == std::string(w) + "-";
        case '~': return !w.empty() && has_word(v, w);
        default: return false;
    }
}

bool compound_matches(const Compound& c, const pugi::xml_node& e) {
    if (!c.type.empty() && c.type != "*" && c.type != e.name()) return false;
    for (const std::string& id : c.ids)
        if (id != e.attribute("id").value()) return false;
    for (const std::string& cls : c.classes)
        if (!has_word(e.attribute("class").value(), cls)) return false;
    for (const AttributeTest& a : c.attributes)
        if (!attribute_matches(a, e)) return false;
    if (c.first_child) {
        for (pugi::xml_node p = e.previous_sibling(); p; p = p.previous_sibling())
            if (p.type() == pugi::node_element) return false;
    }
    return true;
}

// Matches compounds[0..k] with compounds[k] at `e` (right to left, backtracking over ancestors
// for descendant combinators). `budget` bounds the compound tests of one match, so that long
// selectors on deep documents cannot take exponential time; a match that runs out fails.
bool matches_from(const Selector& s, std::size_t k, const pugi::xml_node& e, int& budget) {
    if (--budget < 0 || !compound_matches(s.compounds[k], e)) return false;
    if (k == 0) return true;
    const char comb = s.compounds[k].combinator;
    pugi::xml_node p = e.parent();
    if (comb == '>') return p.type() == pugi::node_element && matches_from(s, k - 1, p, budget);
    for (; p && p.type() == pugi::node_element && budget > 0; p = p.parent())
        if (matches_from(s, k - 1, p, budget)) return true;
    return false;
}

}  // namespace

std::vector<Declaration> parse_declarations(std::string_view text) {
    std::vector<Declaration> out;
    const std::string clean = strip_comments(text);
    std::string_view s = clean;
    while (!s.empty()) {
        const std::size_t semi = s.find(';');
        std::string_view decl = s.substr(0, semi);
        s = semi == std::string_view::npos ? std::string_view{} : s.substr(semi + 1);
        const std::size_t colon = decl.find(':');
        if (colon == std::string_view::npos) continue;
        Declaration d;
        d.name = std::string(trim(decl.substr(0, colon)));
        std::string_view value = trim(decl.substr(colon + 1));
        if (const std::size_t bang = value.rfind('!'); bang != std::string_view::npos) {
            std::string word(trim(value.substr(bang + 1)));
            std::transform(word.begin(), word.end(), word.begin(),
                           [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
            if (word == "important") {
                d.important = true;
                value = trim(value.substr(0, bang));
            }
        }
        d.value = std::string(value);
        if (d.name.empty() || d.value.empty()) continue;
        out.push_back(std::move(d));
    }
    return out;
}

void parse_stylesheet(std::string_view text, StyleSheet& sheet) {
    const std::size_t max_rules = current_limits().css_rules;
    const std::string clean = strip_comments(text);
    const std::string_view s = clean;
    std::size_t i = 0;
    while (i < s.size()) {
        while (i < s.size() && (is_space(s[i]) || s[i] == ';' || s[i] == '}')) ++i;
        if (i >= s.size()) break;
        if (s[i] == '@') {
            // An at-rule: up to its `;`, or its whole { ... } block with nested blocks.
            std::size_t j = i;
            while (j < s.size() && s[j] != ';' && s[j] != '{') ++j;
            if (j < s.size() && s[j] == '{') {
                int depth = 0;
                for (; j < s.size(); ++j) {
                    if (s[j] == '{')
                        ++depth;
                    else if (s[j] == '}' && --depth == 0)
                        break;
                }
            }
            i = j + 1;
            continue;
        }
        const std::size_t open = s.find('{', i);
        if (open == std::string_view::npos) break;
        const std::size_t close = s.find('}', open);
        const std::string_view prelude = s.substr(i, open - i);
        const std::string_view block =
            s.substr(open + 1, (close == std::string_view::npos ? s.size() : close) - open - 1);
        i = close == std::string_view::npos ? s.size() : close + 1;
        const std::vector<Declaration> decls = parse_declarations(block);
        if (decls.empty()) continue;
        std::size_t start = 0;
        while (start <= prelude.size()) {
            const std::size_t comma = prelude.find(',', start);
            const std::string_view one =
                prelude.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start);
            Selector sel;
            if (parse_selector(one, sel)) {
                if (sheet.rules.size() >= max_rules) {
                    sheet.truncated = true;
                    return;
                }
                sheet.rules.push_back({std::move(sel), decls, sheet.rules.size()});
            }
            if (comma == std::string_view::npos) break;
            start = comma + 1;
        }
    }
}

bool matches(const Selector& selector, const pugi::xml_node& element) {
    if (selector.compounds.empty() || element.type() != pugi::node_element) return false;
    int budget = 4096;
    return matches_from(selector, selector.compounds.size() - 1, element, budget);
}

}  // namespace casteljau::css
