// The three importers, each from its format's parsed JSON to a WallDraft (import_draft.hpp).
// Every value is checked where it is read; a refusal names the file and the field.
#pragma once

#include <string>

#include "import_draft.hpp"
#include "import_json.hpp"

namespace l2 {

// Tide (BlueBrain): surfaces[0]'s grid of displays, one pipeserver per process.
WallDraft import_tide(const JsonAt& root, const std::string& name);
// SAGE2: layout x resolution, tile borders in metres as mullions in pixels, the displays.
WallDraft import_sage2(const JsonAt& root, const std::string& name);
// Unreal Engine nDisplay (.ndisplay, 5.x): every viewport of every node, one pipeserver a node.
WallDraft import_ndisplay(const JsonAt& root, const std::string& name);

}  // namespace l2
