// Every program parses its command line with CLI11 and ends the parse the same way, with
// parse_command_line.
//
// Example:
//
//   int main(int argc, char** argv) {
//     CLI::App app{"my_program: what it does"};
//     ...  // options, subcommands; app.callback([&] { ... }) for checks across options
//     if (const std::optional<int> status = l2::parse_command_line(app, argc, argv))
//       return *status;
//     return run(options);
//   }
//
// --help prints the usage and exits 0; a usage error prints one error on stderr, starting with
// the program's name as every other error of the program does, and exits 2 (CLI11's own codes,
// 105, 106 and so on, mean nothing to a script); a subcommand that ran in a callback and threw
// CLI::RuntimeError(status) exits with that status. Checks that need several options at once go
// in the app's callback(), where a CLI::ValidationError is a usage error too.
#pragma once

#include <CLI/CLI.hpp>

#include <cstdio>
#include <optional>
#include <string>

namespace l2 {

inline constexpr int kExitUsageError = 2;

// Parses argv into `app`. Returns the exit status to end the program with, or nullopt to go on.
inline std::optional<int> parse_command_line(CLI::App& app, int argc, char** argv) {
  try {
    app.parse(argc, argv);
    return std::nullopt;
  } catch (const CLI::RuntimeError& e) {
    return e.get_exit_code();
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help is a ParseError that exits 0
    const std::string program = argc > 0 ? argv[0] : "";
    std::fprintf(stderr, "%s: %s\nRun with --help for more information.\n",
                 program.substr(program.find_last_of('/') + 1).c_str(), e.what());
    return kExitUsageError;
  }
}

}  // namespace l2
