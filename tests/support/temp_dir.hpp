// tests/support/temp_dir.hpp: one scratch folder per test process, removed when the process exits.
// ctest runs the test cases of one file in parallel processes, so files written by tests (CLI
// output, stderr captures, generated inputs) must not share a fixed path.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <string>
#include <system_error>

namespace casteljau::testing {

inline const std::filesystem::path& process_temp_dir() {
    struct Dir {
        std::filesystem::path path;
        Dir() : path(std::filesystem::temp_directory_path() / ("casteljau-test-" + std::to_string(::getpid()))) {
            std::filesystem::create_directories(path);
        }
        ~Dir() {
            std::error_code ec;
            std::filesystem::remove_all(path, ec);
        }
    };
    static const Dir dir;
    return dir.path;
}

}  // namespace casteljau::testing
