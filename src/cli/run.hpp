// The command-line front end's entry point, apart from the subcommands' declarations (cli.hpp) so
// that main.cpp and the CLI fuzz target need not compile CLI11.
#pragma once

#include <iosfwd>

namespace casteljau::cli {

// Parses argv and, when `execute`, runs the command it names; returns the exit status (0, 1 bad
// data, 2 bad usage), with help on `out` and the one-line error on `err`. Without `execute` only
// the arguments are parsed and checked (for the CLI fuzz target).
int run(int argc, char** argv, bool execute, std::ostream& out, std::ostream& err);

}  // namespace casteljau::cli
