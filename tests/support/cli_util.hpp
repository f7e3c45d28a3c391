// Test helper: runs the built casteljau CLI and captures its exit status, stdout and stderr.
#pragma once

#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "temp_dir.hpp"

namespace casteljau::test {

struct CliResult {
    int status = -1;
    std::string out, err;
};

inline std::string shell_quote(const std::string& s) {
    std::string q = "'";
    for (char c : s) {
        if (c == '\'')
            q += "'\\''";
        else
            q += c;
    }
    return q + "'";
}

// Runs `casteljau ARGS` (ARGS already quoted for the shell), with `stdin_text` on standard input.
inline CliResult run_cli(const std::string& args, const std::string& stdin_text = "") {
    namespace fs = std::filesystem;
    static int counter = 0;
    const fs::path dir = casteljau::testing::process_temp_dir() / "cli";
    fs::create_directories(dir);
    const std::string base = (dir / std::to_string(counter++)).string();
    {
        std::ofstream in(base + ".in", std::ios::binary);
        in << stdin_text;
    }
    const std::string cmd =
        std::string(CASTELJAU_CLI_PATH) + " " + args + " < " + base + ".in > " + base + ".out 2> " + base + ".err";
    const int raw = std::system(cmd.c_str());
    CliResult r;
    r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
    auto slurp = [](const std::string& p) {
        std::ifstream f(p, std::ios::binary);
        std::stringstream ss;
        ss << f.rdbuf();
        return ss.str();
    };
    r.out = slurp(base + ".out");
    r.err = slurp(base + ".err");
    return r;
}

// A fresh empty folder for a test's output files.
inline std::filesystem::path scratch_dir(const std::string& name) {
    namespace fs = std::filesystem;
    const fs::path d = fs::path(CASTELJAU_BINARY_DIR) / "test-scratch" / name;
    fs::remove_all(d);
    fs::create_directories(d);
    return d;
}

inline bool dir_is_empty(const std::filesystem::path& d) { return std::filesystem::is_empty(d); }

// Writes `s` to `p` as it is (an input file for the CLI).
inline void write_text(const std::filesystem::path& p, const std::string& s) {
    std::ofstream f(p, std::ios::binary);
    f << s;
}

}  // namespace casteljau::test
