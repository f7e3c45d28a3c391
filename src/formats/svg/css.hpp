// Formats stage: a small CSS reader for SVG <style> sheets and style attributes.
//
// Supports what real SVG files use: rules of comma-separated selectors built from type, `*`,
// #id, .class, attribute tests ([a], [a=v], [a~=v], [a^=v], [a$=v], [a*=v], [a|=v]) and
// :first-child, joined by descendant (whitespace) and child (>) combinators; declarations with
// !important; comments. At-rules (@media, @import, @font-face, ...) are skipped whole. Anything
// it cannot read is skipped up to the next `;` or `}` (CSS error recovery), so garbage never
// fails a document. Limits: Limits::css_rules rules (the rest are ignored, with a warning) and
// selectors of at most kMaxCompounds compounds.
// Thread-safety: values; parse and match from any thread.
#pragma once

#include <pugixml.hpp>

#include <string>
#include <string_view>
#include <vector>

namespace casteljau::css {

inline constexpr std::size_t kMaxCompounds = 32;

struct Declaration {
    std::string name, value;
    bool important = false;
};

struct AttributeTest {
    std::string name, value;
    char op = 0;  // 0: present, '=': equals, '~', '^', '$', '*', '|': the CSS operators
};

struct Compound {
    std::string type;  // empty or "*": any
    std::vector<std::string> ids, classes;
    std::vector<AttributeTest> attributes;
    bool first_child = false;
    char combinator = ' ';  // how this compound relates to the one before it: ' ' descendant, '>' child
};

struct Selector {
    std::vector<Compound> compounds;  // left to right
    int specificity = 0;              // ids * 10000 + (classes, attributes, pseudo-classes) * 100 + types
};

struct Rule {
    Selector selector;
    std::vector<Declaration> declarations;
    std::size_t order = 0;  // position in the sheet(s)
};

struct StyleSheet {
    std::vector<Rule> rules;
    bool truncated = false;  // more than Limits::css_rules rules: the rest were ignored
};

// Appends the rules of `text` to `sheet` (one rule per selector of a group).
void parse_stylesheet(std::string_view text, StyleSheet& sheet);
// The declarations of a style attribute or a rule block ("fill: red; stroke: blue !important").
std::vector<Declaration> parse_declarations(std::string_view text);
// Whether `selector` matches `element`.
bool matches(const Selector& selector, const pugi::xml_node& element);

}  // namespace casteljau::css
