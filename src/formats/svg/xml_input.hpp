// Internal (formats): the XML input of the SVG reader before conversion: gzip-compressed input
// (.svgz) inflated, internal DTD entities expanded (entities.cpp), and element names written with
// a prefix bound to the SVG namespace reduced to their local names.
// Thread-safety: plain functions.
#pragma once

#include <pugixml.hpp>

#include <string>
#include <string_view>
#include <vector>

namespace casteljau::svg {

// Inflates gzip data (an .svgz), up to Limits::svgz_bytes. Throws Error(InvalidData) for
// corrupt data, Error(Limit) past the limit.
std::string gunzip(std::string_view data);

// Elements written with a prefix bound to the SVG namespace (<svg:svg xmlns:svg="...">) get their
// local name, so the reader sees <svg>; elements of other namespaces (by prefix or by a default
// namespace other than SVG's) get or keep a prefixed name and are skipped as unknown. Where no
// default namespace is declared, unprefixed elements are taken as SVG. `prefixes` holds the
// prefixes bound to the SVG namespace in scope.
void normalise_namespaces(pugi::xml_node node, std::vector<std::string> prefixes);

// The text of a document whose DOCTYPE declares internal general entities (<!ENTITY name
// "value">) with the references to them replaced (XML 1.0 section 4.4): as markup in content, as
// text in attribute values. Empty when the document declares none (nothing to replace). Throws
// Error(Limit) for entities nested more than a few levels deep (recursive entities, entity bombs)
// or a result past Limits::svgz_bytes.
std::string expand_entities(std::string_view text);

}  // namespace casteljau::svg
