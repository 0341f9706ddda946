// `l2wall golden update`: regenerates the images of the manifest's entries (all, or those
// named) and records, for rendered ones, the GL implementation that made them.
//
// Nothing is written unless every entry asked for is sound — both paths identical, the
// reference within tolerance — and no routing-only (test-pattern) image would change: those
// show where every pixel was routed, so a change there means the routing is broken. Only with
// allow_routing_change does it write such a change.
#pragma once

#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

#include "golden_entry.hpp"

namespace l2 {

struct UpdateOptions {
  GoldenPaths paths;
  std::filesystem::path out = "golden-update";  // runs, and pictures of refused changes
  std::vector<std::string> entries;             // empty: every entry
  bool allow_routing_change = false;
  GoldenTools tools;  // render the rendered entries
};

// Exit code: 0 written (or nothing to change), 1 refused or an entry failed; nothing is
// written then. Throws GoldenError when the update cannot start.
int run_golden_update(const UpdateOptions& options, std::ostream& out);

}  // namespace l2
