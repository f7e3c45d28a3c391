// Test helper: an SVG document of a given pixel size around a body of elements (with the SVG and
// XLink namespaces declared), for tests that draw small documents.
#pragma once

#include <string>

namespace casteljau::test {

inline std::string svg_text(const std::string& body, int width, int height) {
    return "<svg xmlns='http://www.w3.org/2000/svg' xmlns:xlink='http://www.w3.org/1999/xlink' width='" +
           std::to_string(width) + "' height='" + std::to_string(height) + "'>" + body + "</svg>";
}

}  // namespace casteljau::test
