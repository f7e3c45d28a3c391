// A small golden-image helper for the text tests (tests/support/golden.hpp, the shared harness, could
// replace it). golden/text/NAME.png is compared with the rendering
// under explicit tolerances (max and mean absolute difference per channel, 1/255 units). On a
// mismatch NAME.actual.png and NAME.diff.png are written to <build>/golden-out/text/. Setting the
// environment variable CASTELJAU_UPDATE_GOLDEN=1 rewrites the golden instead (an explicit opt-in;
// each golden test checks its picture against FreeType before it gets here).
#pragma once

#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "casteljau/png.hpp"
#include "golden.hpp"
#include "text_support.hpp"

namespace text_test {

inline void check_golden(const std::string& name, const casteljau::Pixmap& actual, int max_tol, double mean_tol) {
    // The shared harness (tests/support/golden.hpp); the caller compared with FreeType first.
    casteljau::golden::check_golden("text/" + name, actual, {max_tol, mean_tol},
                                    {true, "text checked against FreeType (supersampled) before this call"});
}

}  // namespace text_test
