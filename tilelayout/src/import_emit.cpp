// Writes an importer's WallDraft as wall-file text, choosing the tiling, the pipeservers and
// their framebuffers by planning the wall with the planner itself (suggest_fit), so what it
// writes is a wall every program accepts.
#include <fmt/format.h>

#include <algorithm>
#include <climits>

#include "import_draft.hpp"
#include "tilelayout/fit.hpp"
#include "tilelayout/planner.hpp"
#include "tilelayout/tile_layout.hpp"
#include "tilelayout/toml_text.hpp"
#include "tilelayout/wall_file.hpp"

namespace l2 {
namespace {

constexpr int kMaxTiles = 4096;  // [tiling] tile_count

// Comment text on one line and in plain ASCII, whatever the file's strings hold.
std::string comment_text(const std::string& s) {
  std::string out;
  for (const char c : s) {
    const auto u = static_cast<unsigned char>(c);
    out += u >= 0x20 && u < 0x7f ? c : '?';
  }
  return out;
}

struct Choice {
  int pipeservers = 1;
  int tiles = 1;
  int fb_width = kMaxFramebufferSide, fb_height = kMaxFramebufferSide;
};

// Hosts in the order mpirun fills a hostfile's slots: each host's pipeservers together, hosts
// in the order they first appear, every process or node of the file `per` times.
std::vector<std::string> pipeserver_hosts(const std::vector<std::string>& hosts, int per) {
  std::vector<std::string> order;
  for (const std::string& h : hosts) {
    if (std::find(order.begin(), order.end(), h) == order.end()) order.push_back(h);
  }
  std::vector<std::string> out;
  for (const std::string& h : order) {
    const auto n = std::count(hosts.begin(), hosts.end(), h) * per;
    out.insert(out.end(), static_cast<std::size_t>(n), h);
  }
  return out;
}

// `with_keys`: each display's further keys too. Planning reads the wall without them: the files
// they name are written beside the wall file later, and the plan does not depend on them.
std::string render(const WallDraft& d, const std::vector<DraftDisplay>& displays, const Choice& c,
                   const std::vector<std::string>& hosts, bool with_keys) {
  std::string t;
  for (const std::string& line : d.header) t += "# " + comment_text(line) + "\n";
  if (!d.notes.empty()) {
    t += "#\n# What the wall file cannot carry, or had to guess:\n";
    for (const std::string& n : d.notes) t += "#   - " + comment_text(n) + "\n";
  }
  t += fmt::format("\nname = {}\n", toml_quoted(d.name));
  if (d.grid) {
    const DraftGrid& g = *d.grid;
    t += fmt::format(
        "\n[display_grid]\ncolumns = {}\nrows = {}\nwidth = {}\nheight = {}\n"
        "mullion_x = {}\nmullion_y = {}\n",
        g.columns, g.rows, g.width, g.height, g.mullion_x, g.mullion_y);
    t += "# Display ids run row by row; where each came from:\n";
    for (std::size_t i = 0; i < displays.size(); ++i)
      t += fmt::format("#   display {}: {}\n", i, comment_text(displays[i].origin));
  } else {
    for (std::size_t i = 0; i < displays.size(); ++i) {
      const DraftDisplay& p = displays[i];
      t += fmt::format("\n[[display]]  # {}\nid = {}\nwidth = {}\nheight = {}\nx = {}\ny = {}\n",
                       comment_text(p.origin), i, p.width, p.height, p.x, p.y);
      if (p.orientation.rotation != 0) t += fmt::format("rotation = {}\n", p.orientation.rotation);
      if (p.orientation.flip != Flip::None)
        t += fmt::format("flip = \"{}\"\n", kFlipNames[static_cast<int>(p.orientation.flip)]);
      if (with_keys) {
        for (const std::string& key : p.keys) t += key + "\n";
      }
    }
  }
  t += fmt::format(
      "\n[tiling]\n# k-d tiles dealt round-robin: every pipeserver gets the same number, cut to "
      "equal visible area.\nkind = \"kd\"\ntile_count = {}\n",
      c.tiles);
  t += "\n[pipeservers]\n";
  if (hosts.empty()) {
    t += "# The file names no render hosts: one pipeserver per display.\n";
  } else {
    t += "# One per process or node the file names (tilelayout import --hostfile writes them "
         "for mpirun), by pipeserver:\n";
    for (std::size_t i = 0; i < hosts.size(); ++i)
      t += fmt::format("#   {}: {}\n", i, comment_text(hosts[i]));
  }
  t += fmt::format(
      "count = {}\n# The smallest framebuffer that holds every pipeserver's tiles.\n"
      "framebuffer_width = {}\nframebuffer_height = {}\nassignment = \"round-robin\"\n",
      c.pipeservers, c.fb_width, c.fb_height);
  const Wall defaults;
  if (c.fb_width > defaults.board_max_width || c.fb_height > defaults.board_max_height) {
    t += fmt::format(
        "\n[mesh]\n# A framebuffer is one board input: the boards take one this large.\n"
        "board_max_width = {}\nboard_max_height = {}\n",
        std::max(c.fb_width, defaults.board_max_width),
        std::max(c.fb_height, defaults.board_max_height));
  }
  return t;
}

Wall parse_draft(const std::string& text, const std::string& file) {
  try {
    return parse_wall(text, file + " (imported)");
  } catch (const LayoutError& e) {
    throw LayoutError(
        fmt::format("{}: the imported displays do not make a wall: {}", file, e.what()));
  }
}

}  // namespace

void too_many_displays(const std::string& file, const std::string& where, long long count) {
  throw LayoutError(
      fmt::format("{}: {}: {} displays, more than the {} one mesh addresses, which is all an "
                  "import makes (a wall of more is served by several meshes: docs/wall-file.md)",
                  file, where, count, kMaxImportedDisplays));
}

std::string emit_wall(const WallDraft& draft, const std::string& file,
                      std::vector<std::string>& hosts_out) {
  if (draft.displays.empty()) throw LayoutError(fmt::format("{}: no displays to import", file));
  // The canvas starts at 0,0: a file may place its windows anywhere on a desktop.
  std::vector<DraftDisplay> displays = draft.displays;
  int left = INT_MAX, top = INT_MAX, right = INT_MIN, bottom = INT_MIN;
  for (const DraftDisplay& p : displays) {
    const bool turned = p.orientation.turned();
    left = std::min(left, p.x);
    top = std::min(top, p.y);
    right = std::max(right, p.x + (turned ? p.height : p.width));
    bottom = std::max(bottom, p.y + (turned ? p.width : p.height));
  }
  if (right - left > kMaxCanvasSide || bottom - top > kMaxCanvasSide) {
    throw LayoutError(fmt::format(
        "{}: the displays span {}x{} pixels, more than the {}x{} a wall's canvas may have", file,
        right - left, bottom - top, kMaxCanvasSide, kMaxCanvasSide));
  }
  for (DraftDisplay& p : displays) {
    p.x -= left;
    p.y -= top;
  }

  const int named = static_cast<int>(draft.hosts.size());
  const int base = named > 0 ? named : static_cast<int>(displays.size());
  // More pipeservers per host, then more tiles per pipeserver, until the framebuffers hold
  // the wall and every pipeserver has something to show.
  for (int per = 1; base * per <= kMaxPipeservers; per *= 2) {
    const std::vector<std::string> hosts =
        named > 0 ? pipeserver_hosts(draft.hosts, per) : std::vector<std::string>{};
    for (int tiles = 1; tiles <= 4 && base * per * tiles <= kMaxTiles; tiles *= 2) {
      Choice c{base * per, base * per * tiles};
      const FitSuggestions fit =
          suggest_fit(parse_draft(render(draft, displays, c, hosts, false), file));
      if (fit.idle_pipeserver || !fit.smallest) continue;
      c.fb_width = fit.smallest->first;
      c.fb_height = fit.smallest->second;
      const Wall wall = parse_draft(render(draft, displays, c, hosts, false), file);
      try {
        plan_layout(wall);  // what the user will run: it must plan
      } catch (const LayoutError& e) {
        throw LayoutError(fmt::format("{}: the imported wall does not plan: {}", file, e.what()));
      }
      hosts_out = hosts;
      return render(draft, displays, c, hosts, true);
    }
  }
  throw LayoutError(fmt::format(
      "{}: no framebuffers of up to {}x{} hold the wall's {} displays, even with {} pipeservers",
      file, kMaxFramebufferSide, kMaxFramebufferSide, displays.size(), kMaxPipeservers));
}

}  // namespace l2
