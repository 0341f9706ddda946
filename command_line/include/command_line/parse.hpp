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
// in the app's callback(), where a CLI::ValidationError is a usage error too. An option nobody
// defines ("The following arguments were not expected: --refrsh") is followed by the closest
// option of that (sub)command when one is close: " (did you mean --refresh?)".
#pragma once

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace l2 {

inline constexpr int kExitUsageError = 2;

// Edits (insert, delete, replace a character, swap two neighbours) that make `a` into `b`.
inline std::size_t edit_distance(std::string_view a, std::string_view b) {
  // Three rows of the table: two back (for a swap), the last, this one.
  std::vector<std::size_t> before(b.size() + 1), last(b.size() + 1), row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) last[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t replace = last[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      row[j] = std::min({last[j] + 1, row[j - 1] + 1, replace});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        row[j] = std::min(row[j], before[j - 2] + 1);
    }
    std::swap(before, last);
    std::swap(last, row);
  }
  return last[b.size()];
}

// Of `names`, the one closest to `typed` when it is close (at most 2 edits, or a third of the
// name's length for a long one): what the user probably meant. Empty when none is, or `typed`
// is one of them.
inline std::string closest_name(std::string_view typed, const std::vector<std::string>& names) {
  std::string best;
  std::size_t best_distance = 0;
  for (const std::string& name : names) {
    const std::size_t d = edit_distance(typed, name);
    if (d == 0) return {};
    if (d > std::max<std::size_t>(2, name.size() / 3)) continue;
    if (best.empty() || d < best_distance) {
      best = name;
      best_distance = d;
    }
  }
  return best;
}

namespace parse_detail {

// The (sub)command whose left-over arguments CLI11 refused: as it checks them, the first from
// the top that takes no extras and has some.
inline const CLI::App* app_with_extras(const CLI::App& app) {
  if (!app.get_allow_extras() && !app.get_prefix_command() && app.remaining_size() > 0) return &app;
  for (const CLI::App* sub : app.get_subcommands()) {
    if (const CLI::App* found = app_with_extras(*sub)) return found;
  }
  return nullptr;
}

// The long options of `app`, as typed (--name), with those of its option groups.
inline void add_long_options(const CLI::App& app, std::vector<std::string>& names) {
  for (const CLI::Option* option : app.get_options()) {
    for (const std::string& name : option->get_lnames()) names.push_back("--" + name);
  }
  for (const CLI::App* group :
       app.get_subcommands([](const CLI::App* sub) { return sub->get_name().empty(); }))
    add_long_options(*group, names);
}

// " (did you mean --refresh?)" for the options `app` refused that are close to one it has; for
// several, " (did you mean --refresh for --refrsh, --frames for --frmes?)". Empty without any.
inline std::string did_you_mean(const CLI::App& app) {
  const CLI::App* refusing = app_with_extras(app);
  if (refusing == nullptr) return {};
  std::vector<std::string> names;
  add_long_options(*refusing, names);
  std::vector<std::pair<std::string, std::string>> meant;  // typed, meant
  for (const std::string& arg : refusing->remaining()) {
    if (arg.size() < 2 || arg[0] != '-') continue;  // a value or a word, not an option
    const std::string typed = arg.substr(0, arg.find('='));
    if (std::string name = closest_name(typed, names); !name.empty())
      meant.emplace_back(typed, std::move(name));
  }
  if (meant.empty()) return {};
  if (meant.size() == 1) return " (did you mean " + meant.front().second + "?)";
  std::string text;
  for (const auto& [typed, name] : meant)
    text += (text.empty() ? "" : ", ") + name + " for " + typed;
  return " (did you mean " + text + "?)";
}

}  // namespace parse_detail

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
    const std::string hint =
        dynamic_cast<const CLI::ExtrasError*>(&e) ? parse_detail::did_you_mean(app) : "";
    std::fprintf(stderr, "%s: %s%s\nRun with --help for more information.\n",
                 program.substr(program.find_last_of('/') + 1).c_str(), e.what(), hint.c_str());
    return kExitUsageError;
  }
}

}  // namespace l2
