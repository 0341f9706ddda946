// The control page in Debian's Chromium (tests/browser/), driven by a script of playwright-core
// against a live run: whether it can run here, and what a script saw. Needs L2_SOURCE_DIR.
#pragma once

#include <nlohmann/json.hpp>

#include "control_page_run.hpp"

namespace l2::testing_support {

// Why the browser test cannot run here, or empty.
inline std::string browser_missing() {
  const fs::path browser = fs::path(L2_SOURCE_DIR) / "tests/browser";
  if (!fs::exists("/usr/bin/chromium")) return "no /usr/bin/chromium (scripts/install-deps.sh)";
  if (std::system("command -v node >/dev/null 2>&1") != 0) return "no node";
  if (!fs::exists(browser / "node_modules/playwright-core"))
    return "no tests/browser/node_modules (scripts/install-deps.sh runs npm ci there)";
  return {};
}

// What tests/browser/SCRIPT.mjs saw of a session run's page (its JSON line), or an empty object
// with the failure recorded.
inline nlohmann::json session_script(PageRun& run, const std::string& script) {
  const fs::path dir = run.out().parent_path();
  const fs::path seen = dir / (script + ".json"), log = dir / (script + ".log");
  const std::string command =
      fmt::format("exec node '{}' '{}' > '{}' 2> '{}'",
                  (fs::path(L2_SOURCE_DIR) / "tests/browser" / (script + ".mjs")).string(),
                  run.url(), seen.string(), log.string());
  ChildProcess browser({"/bin/sh", "-c", command});
  const auto ended = browser.wait_for(120s);
  if (!ended) ADD_FAILURE() << "the browser script did not end";
  if (!ended || ended->code != 0) {
    ADD_FAILURE() << slurp(log) << run.output();
    return nlohmann::json::object();
  }
  return nlohmann::json::parse(slurp(seen));
}

}  // namespace l2::testing_support
