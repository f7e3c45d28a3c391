// Test support: skipping a test case whose data or environment is absent, and where the shared
// data folder is.
//
// A skipped test case calls CASTELJAU_SKIP("why") and returns. The reason is printed on standard
// output, the skip counts as a passing assertion (so `-w NoAssertions` accepts it), and when every
// test case a run selected was skipped, the test binary exits with kSkipExitCode, which ctest
// reports as "Skipped" (SKIP_RETURN_CODE in tests/CMakeLists.txt). ctest runs one test case per
// process, so a skipped case shows as skipped there and never as passed.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>

namespace casteljau::test {

inline constexpr int kSkipExitCode = 77;

// Records that the running test case skipped (main.cpp reads the count); prints the reason.
void record_skip(const std::string& reason);
// How many distinct test cases skipped in this process.
int skipped_test_cases();

// The shared data folder: $CASTELJAU_SHARED_DIR when set (handy in a git worktree), otherwise
// ../shared next to the source tree.
inline std::filesystem::path shared_dir() {
    if (const char* env = std::getenv("CASTELJAU_SHARED_DIR"); env != nullptr && *env != '\0') return env;
    return std::filesystem::path(CASTELJAU_SOURCE_DIR) / ".." / "shared";
}

}  // namespace casteljau::test

// Skips the rest of the current test case: CASTELJAU_SKIP("no " << path). Use only at the top
// level of a TEST_CASE body (it returns from the enclosing function).
#define CASTELJAU_SKIP(message)                                       \
    do {                                                              \
        std::ostringstream casteljau_skip_reason_;                    \
        casteljau_skip_reason_ << message;                            \
        ::casteljau::test::record_skip(casteljau_skip_reason_.str()); \
        return;                                                       \
    } while (false)
