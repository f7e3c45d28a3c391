// tests/support/golden.hpp: the golden-image harness. Test-only.
//
// check_golden(name, actual, Tolerance{max_abs, mean_abs}, validated) compares a rendered Pixmap
// with golden/NAME.png (NAME may contain folders, e.g. "raster/star_nonzero"):
//   - the difference of a pixel is the largest absolute difference over its four premultiplied
//     channels (0..255); the check fails when the largest pixel difference exceeds max_abs or their
//     mean over the image exceeds mean_abs, or when the sizes differ;
//   - on failure it writes NAME.actual.png and NAME.diff.png (red = 8 x difference, clamped; the
//     expected image shows through faintly in green and blue) under CASTELJAU_BINARY_DIR/golden-out/
//     and fails with the max, the mean and the worst pixel;
//   - a missing golden is a failure (the actual image is written for inspection).
// Regenerating is an explicit opt-in: with CASTELJAU_UPDATE_GOLDEN=1 in the environment the golden
// is (re)written and the difference to the previous one is reported, not failed. A golden may only
// be written by a test that validated the very same image against the independent reference: the
// caller passes that verdict as `validated`, and a golden is never written without it.
// The tolerance is explicit in every call.
#pragma once

#include <string>

#include "casteljau/paint.hpp"

namespace casteljau::golden {

struct Tolerance {
    int max_abs = 0;        // largest allowed per-pixel difference (0..255)
    double mean_abs = 0.0;  // largest allowed mean of the per-pixel differences
};

// The verdict of the independent check made in the same test on the same image.
struct Validation {
    bool passed = false;
    std::string summary;  // what was checked and how it came out (goes into messages)
};

struct Difference {
    bool size_mismatch = false;
    int max_abs = 0;
    double mean_abs = 0;
    int worst_x = 0, worst_y = 0;
    PremulPixel expected, actual;  // at the worst pixel
    std::string text() const;
};

Difference difference(const Pixmap& expected, const Pixmap& actual);
// The magnified difference picture described above (sizes must match).
Pixmap difference_image(const Pixmap& expected, const Pixmap& actual);

// The harness without Catch2, for its own tests: directories and update mode are parameters.
struct Setup {
    std::string golden_dir;  // where NAME.png lives
    std::string out_dir;     // where NAME.actual.png / NAME.diff.png go
    bool update = false;
};
struct Outcome {
    bool ok = false;  // matched within tolerance, or (update mode) written
    bool wrote_golden = false;
    bool wrote_outputs = false;
    std::string message;  // one paragraph for the test log
};
Outcome compare_golden(const Setup& setup, const std::string& name, const Pixmap& actual, const Tolerance& tol,
                       const Validation& validated);

// The default setup: CASTELJAU_SOURCE_DIR/golden, CASTELJAU_BINARY_DIR/golden-out, update mode
// from CASTELJAU_UPDATE_GOLDEN=1.
Setup default_setup();

// Catch2 front end: CHECKs the outcome (WARNs the message in update mode). Returns outcome.ok.
bool check_golden(const std::string& name, const Pixmap& actual, const Tolerance& tol, const Validation& validated);

}  // namespace casteljau::golden
