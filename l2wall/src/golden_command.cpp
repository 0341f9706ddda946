#include "golden_command.hpp"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <iostream>
#include <memory>

#include "base/stop_signals.hpp"
#include "command_line/checks.hpp"
#include "command_line/program_paths.hpp"
#include "golden/golden_check.hpp"
#include "golden/golden_rendered.hpp"
#include "golden/golden_update.hpp"

namespace l2 {

namespace {

// The golden folder and the walls where l2wall runs from: the installed files, or the working
// tree the build is in, or the one of the current folder. Found nowhere: the relative paths,
// which the check then names as missing.
GoldenPaths default_paths() {
  const std::filesystem::path goldens = std::filesystem::path("tests") / "golden_images";
  const std::filesystem::path root =
      project_files(goldens / "manifest.toml").value_or(std::filesystem::path("."));
  return {root / goldens, root};
}

void add_path_options(CLI::App& cmd, GoldenPaths& paths, std::vector<std::string>& entries) {
  cmd.add_option("--goldens", paths.goldens,
                 "golden folder: manifest.toml and <entry>/display-<id>.png")
      ->type_name("DIR")
      ->capture_default_str();
  cmd.add_option("--root", paths.root, "where the manifest's wall paths start (the repository)")
      ->type_name("DIR")
      ->capture_default_str();
  cmd.add_option("--entry", entries, "only this entry (repeatable); default: every entry")
      ->type_name("NAME");
}

// Runs `body` and ends the parse with its exit code; errors are one line on stderr, exit 2.
// SIGINT and SIGTERM are recorded, not taken at once: they end the body between entries, or
// once an entry's commands ended (its `l2wall run` removes its shared memory as it ends).
template <class Body>
[[noreturn]] void finish(Body body) {
  catch_stop_signals();
  int code = 2;
  try {
    code = body();
  } catch (const GoldenStopped& e) {
    // Its commands ended (golden_rendered.hpp): the exit status says the signal, as a shell's.
    std::fprintf(stderr, "l2wall golden: %s\n", e.what());
    end_by_stop_signal();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "l2wall golden: %s\n", e.what());
  }
  std::cout << std::flush;
  throw CLI::RuntimeError(code);
}

// This l2wall, and the pipeserver built beside it (as `l2wall run` uses by default).
GoldenTools tools() {
  return {std::filesystem::read_symlink("/proc/self/exe").string(),
          sibling_program("pipeserver").string()};
}

// Unasked, the default golden folder is the project's own (the source tree, or the installed
// files): an update writes only into a folder it was told to.
[[noreturn]] void refuse_default_goldens(const GoldenPaths& paths) {
  std::fprintf(stderr,
               "l2wall golden update: give --goldens DIR, the golden folder to write; the "
               "default, %s, is the project's own (to regenerate it, name it)\n",
               paths.goldens.string().c_str());
  throw CLI::RuntimeError(2);
}

}  // namespace

void add_golden_command(CLI::App& app) {
  CLI::App* golden = app.add_subcommand(
      "golden",
      "golden-image regression of reassembly: every example wall's test pattern and rendered "
      "scenes, compared with tests/golden_images/ (see its README.md)");
  golden->require_subcommand(1);

  auto check = std::make_shared<CheckOptions>();
  check->paths = default_paths();
  CLI::App* c = golden->add_subcommand(
      "check",
      "reproduce every entry and compare: the emulator's displays with the golden images "
      "(exactly; within the entry's tolerance when a rendered entry was made by another Mesa), "
      "the vizserver path with the emulator (exactly), the emulator with the reference "
      "(test pattern exactly, reference render within the documented tolerance). A mismatch "
      "writes OUT/<entry>/display-<id>-actual.png and -diff.png (differing pixels magenta on a "
      "dimmed copy, marked by yellow squares) and prints one line per display. Exit 0 all "
      "pass, 1 a mismatch, 2 the check could not run");
  add_path_options(*c, check->paths, check->entries);
  c->add_option("--out", check->out, "where actual images and diff pictures go")
      ->check(non_empty_path())
      ->type_name("DIR")
      ->capture_default_str();
  c->add_option("--inputs", check->inputs,
                "route captured frames instead: DIR/scanout-<i>.png for every pipeserver i (as "
                "`tilelayout --wall WALL --canvas-pattern --scanout DIR` names them) through the "
                "emulator and compare the displays with the golden images of the one "
                "routing-only --entry")
      ->type_name("DIR")
      ->check(CLI::ExistingDirectory);
  c->add_flag("--write-actual", check->write_actual,
              "write every display's actual image to OUT/<entry>/, also when it passes");
  c->callback([check] {
    check->tools = tools();
    finish([&] { return run_golden_check(*check, std::cout); });
  });

  auto update = std::make_shared<UpdateOptions>();
  update->paths = default_paths();
  CLI::App* u = golden->add_subcommand(
      "update",
      "regenerate the golden images of every entry (or --entry) and record the Mesa version of "
      "rendered ones in the manifest. Writes nothing unless every entry is sound (both paths "
      "identical, reference within tolerance); refuses to change a routing-only (test-pattern) "
      "image unless --allow-routing-change. Needs --goldens: it never writes into the project's "
      "own golden folder unasked");
  add_path_options(*u, update->paths, update->entries);
  u->add_option("--out", update->out, "where the runs and pictures of refused changes go")
      ->check(non_empty_path())
      ->type_name("DIR")
      ->capture_default_str();
  u->add_flag("--allow-routing-change", update->allow_routing_change,
              "write changed routing-only (test-pattern) images too: only when the routing or "
              "the test pattern was changed on purpose");
  u->callback([update, u] {
    update->tools = tools();
    if (u->get_option("--goldens")->count() == 0) refuse_default_goldens(update->paths);
    finish([&] { return run_golden_update(*update, std::cout); });
  });
}

}  // namespace l2
