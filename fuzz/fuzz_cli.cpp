// libFuzzer target: the command line's argument parsing (src/cli: every subcommand's options,
// validators and value conversions through CLI11), without running the commands. The input is
// split at NUL bytes into arguments after "casteljau". Invariant: every argument list ends in an
// exit status of 0, 1 or 2, never in an exception escaping or a crash.
#include <sstream>
#include <string>
#include <vector>

#include "cli/run.hpp"
#include "harness.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size > 4096) return 0;
    std::vector<std::string> args{"casteljau"};
    std::string cur;
    for (std::size_t i = 0; i < size; ++i) {
        if (data[i] == 0) {
            args.push_back(cur);
            cur.clear();
        } else {
            cur += static_cast<char>(data[i]);
        }
    }
    args.push_back(cur);
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    std::ostringstream out, err;
    const int status = casteljau::cli::run(static_cast<int>(args.size()), argv.data(), false, out, err);
    casteljau::fuzz::require(status >= 0 && status <= 2, "the command line returned an unknown exit status");
    return 0;
}
