// The command line's driver: registers the subcommands, parses the arguments, runs the chosen
// command and maps errors to exit codes (1: bad data, 2: bad usage) with a one-line message.
#include <algorithm>
#include <cstdio>
#include <exception>
#include <iterator>
#include <ostream>
#include <string_view>

#include "casteljau/error.hpp"
#include "cli/cli.hpp"

namespace casteljau::cli {

int run(int argc, char** argv, bool execute, std::ostream& out, std::ostream& err) {
    CLI::App app{"casteljau: vector outlines to anti-aliased PNG (exact-area rasterizer)", "casteljau"};
    app.require_subcommand(1);
    app.set_version_flag("--version", "casteljau 0.1.0");
    // Subcommands: one registration function per src/cli/cmd_*.cpp file. Building CLI11's option
    // tables costs more than some whole runs (one letter of text), so when the first argument
    // names a command only that command is registered; otherwise (help, version, a mistake) all
    // are, so help and error messages list every command.
    struct Command {
        const char* name;
        void (*add)(CLI::App&);
    };
    static constexpr Command kCommands[] = {
        {"path", cli::register_path},     {"svg", cli::register_svg},         {"bezier", cli::register_bezier},
        {"spline", cli::register_spline}, {"surface", cli::register_surface}, {"text", cli::register_text},
        {"map", cli::register_map},       {"tiles", cli::register_tiles},     {"tiles-merge", cli::register_tiles},
    };
    // One registration function may add several commands (tiles and tiles-merge): each runs once.
    const Command* only = nullptr;
    for (const Command& c : kCommands)
        if (argc > 1 && std::string_view(argv[1]) == c.name) only = &c;
    void (*added[std::size(kCommands)])(CLI::App&) = {};
    std::size_t n_added = 0;
    for (const Command& c : kCommands) {
        if (only != nullptr && only != &c) continue;
        if (std::find(added, added + n_added, c.add) != added + n_added) continue;
        c.add(app);
        added[n_added++] = c.add;
    }
    // Without `execute`, stop once parsing, validation and requirements are done: CLI11 calls the
    // main app's parse-complete callback before any subcommand's callback.
    struct ParsedOnly {};
    if (!execute) app.parse_complete_callback([] { throw ParsedOnly{}; });
    try {
        app.parse(argc, argv);
    } catch (const ParsedOnly&) { return 0; } catch (const CLI::CallForHelp& e) {
        return app.exit(e, out, err);
    } catch (const CLI::CallForAllHelp& e) { return app.exit(e, out, err); } catch (const CLI::CallForVersion& e) {
        return app.exit(e, out, err);
    } catch (const CLI::ParseError& e) {
        err << "casteljau: error: " << e.what() << " (see casteljau --help)\n";
        return 2;
    } catch (const cli::UsageError& e) {
        err << "casteljau: error: " << e.what() << "\n";
        return 2;
    } catch (const casteljau::Error& e) {
        err << "casteljau: error: " << e.what() << "\n";
        return e.kind() == casteljau::ErrorKind::InvalidArgument ? 2 : 1;
    } catch (const std::bad_alloc&) {
        err << "casteljau: error: out of memory\n";
        return 1;
    } catch (const std::exception& e) {
        err << "casteljau: error: " << e.what() << "\n";
        return 1;
    }
    return 0;
}

}  // namespace casteljau::cli
