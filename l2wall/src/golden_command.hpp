// The `l2wall golden` subcommand: `check` and `update` of the golden images of reassembly
// (tests/golden_images/). Its parts are in golden_check.hpp and golden_update.hpp.
#pragma once

namespace CLI {
class App;
}

namespace l2 {

// Adds `golden check` and `golden update` to `app`. Each runs during parsing and ends it with
// its exit code (a CLI::RuntimeError, which CLI11_PARSE returns without printing anything).
void add_golden_command(CLI::App& app);

}  // namespace l2
