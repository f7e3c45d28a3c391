// Golden images for the curve pictures: golden/curves/NAME.png through the shared harness
// (tests/support/golden.hpp: explicit tolerances, NAME.actual.png / NAME.diff.png in <build>/golden-out on
// a mismatch, CASTELJAU_UPDATE_GOLDEN=1 to rewrite). Each caller checks its picture independently
// (pixels at computed positions) before it gets here.
#pragma once

#include <string>

#include "golden.hpp"

namespace curves_test {

inline void check_golden(const std::string& dir, const std::string& name, const casteljau::Pixmap& actual, int max_tol,
                         double mean_tol) {
    casteljau::golden::check_golden(dir + "/" + name, actual, {max_tol, mean_tol},
                                    {true, "picture checked independently by the CHECKs before this call"});
}

}  // namespace curves_test
