#!/usr/bin/env bash
# Regenerates the libFuzzer dictionaries in fuzz/dict/ from the keywords the readers themselves
# compare against (string literals in their sources), plus each syntax's punctuation. run_smoke.sh
# passes fuzz/dict/NAME.dict to a target when it exists (NAME: the target without fuzz_).
# Usage: fuzz/make_dicts.sh   (from anywhere; rewrites fuzz/dict/*.dict)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
out=fuzz/dict
mkdir -p "$out"
# Quoted identifiers (letters, digits, '-', ':', '_') of at least two characters, one per line.
words() { grep -ohE '"[a-zA-Z@:][a-zA-Z0-9:_-]{1,40}"' "$@" | sort -u; }
# In libFuzzer's dictionary syntax a backslash or a double quote inside an entry takes a backslash before it.
literal() { for w in "$@"; do w=${w//\\/\\\\}; printf '"%s"\n' "${w//\"/\\\"}"; done; }
header() { printf '# libFuzzer dictionary for %s, made by fuzz/make_dicts.sh from %s\n' "$1" "$2"; }

{
  header fuzz_svg "src/formats/svg/*.cpp and the colour names"
  words src/formats/svg/*.cpp src/paint/named_colors.cpp
  literal '<svg' '</svg>' '<?xml' '<!DOCTYPE' '<![CDATA[' ']]>' '<!--' '-->' '/>' '="' 'xmlns="http://www.w3.org/2000/svg"' \
    'xmlns:xlink="http://www.w3.org/1999/xlink"' 'xlink:href="#' 'href="#' 'url(#' 'data:image/png;base64,' \
    'data:image/svg+xml;base64,' '&#x' '&amp;' '<!ENTITY' '%' 'px' 'em' 'ex' 'pt' 'mm' 'deg' 'rad' 'e-' '1e30' 'NaN' \
    'matrix(' 'translate(' 'scale(' 'rotate(' 'skewX(' 'skewY(' 'rgb(' 'rgba(' 'hsl(' '#' '{' '}' ';' '!important'
} > "$out/svg.dict"

{
  header fuzz_css "src/formats/svg/css.cpp and the SVG properties"
  # The property names: the SVG conversion's files, without the filter and text layout engines it calls.
  words $(ls src/formats/svg/*.cpp | grep -v -e /filter_ -e /text_layout.cpp -e /text_fonts.cpp -e /transform.cpp)
  literal '{' '}' ';' ':' ',' '*' '>' '+' '~' '[' ']' '=' '~=' '|=' '^=' '$=' '*=' '.' '#' '/*' '*/' '@import' '@media' \
    ':first-child' '!important' 'url(' '"' "'"
} > "$out/css.dict"

{
  header fuzz_map_data "src/formats/geojson.cpp, topojson.cpp, json_properties.cpp, src/json/json_support.cpp and src/map/map_style.cpp"
  words src/formats/geojson.cpp src/formats/topojson.cpp src/formats/json_properties.cpp src/json/json_support.cpp src/map/map_style.cpp
  literal '{' '}' '[' ']' ':' ',' '{"type":' '"coordinates":[' '"arcs":[' '[[' ']]' '-180' '180' '-90' '90' '1e308' \
    '-0' '0.5' '\u0000' '\n'
} > "$out/map_data.dict"

{
  header fuzz_svg_path "SVG path data and points syntax"
  literal M m L l H h V v C c S s Q q T t A a Z z ',' ' ' '.' '-' '+' 'e' 'E' 'e-' '1e308' '1e-320' '.5.5' '0 0 1' \
    '1 1 0' 'nan' 'inf'
} > "$out/svg_path.dict"
for f in "$out"/*.dict; do echo "$f: $(grep -vc '^#' "$f") entries"; done
