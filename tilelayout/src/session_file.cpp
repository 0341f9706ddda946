#include "tilelayout/session_file.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "tilelayout/tile_layout.hpp"
#include "toml_fields.hpp"

namespace l2 {

namespace {

// The sources a window may show: those with a file first.
const std::vector<std::string_view> kSources{"picture", "movie",      "mesh",    "vnc", "strips",
                                             "hotspot", "isosurface", "patches", "swap"};

// A vnc window's content is the desktop's address, not a file.
bool takes_content(std::string_view source) {
  return source == "picture" || source == "movie" || source == "mesh" || source == "vnc";
}

// Which fits a source takes: pixels are laid four ways, a model framed two, the generated
// scenes frame themselves.
std::vector<std::string_view> fits_of(std::string_view source) {
  if (source == "picture" || source == "movie" || source == "vnc")
    return {"fit", "fill", "stretch", "1:1"};
  if (source == "mesh") return {"fit", "fill"};
  return {};
}

SessionWindow read_window(const TomlFields& f, const std::filesystem::path& folder) {
  SessionWindow w;
  const int source = f.choice("source", kSources, -1);
  if (source < 0) f.source().fail(f.line(), f.field("source"), "missing (required)");
  w.source = std::string(kSources[static_cast<std::size_t>(source)]);
  const auto content = f.string("content");
  if (content && !takes_content(w.source))
    f.fail("content", fmt::format("a {} window takes no file", w.source));
  if (!content && w.source != "mesh" && takes_content(w.source))
    f.source().fail(f.line(), f.field("content"),
                    w.source == "vnc"
                        ? std::string("missing (a vnc window needs its desktop, HOST:DISPLAY)")
                        : fmt::format("missing (a {} window needs its file)", w.source));
  if (content && w.source == "vnc" && content->empty())
    f.fail("content", "empty (a vnc window needs its desktop, HOST:DISPLAY)");
  if (content) w.content = w.source == "vnc" ? std::filesystem::path(*content) : folder / *content;
  const auto password = f.string("password_file");
  if (password && w.source != "vnc")
    f.fail("password_file", fmt::format("a {} window takes no password", w.source));
  if (password) w.password_file = folder / *password;
  w.on_canvas.x = f.required_integer("x", -kWindowReach, kWindowReach);
  w.on_canvas.y = f.required_integer("y", -kWindowReach, kWindowReach);
  w.on_canvas.w = f.required_integer("width", 1, kMaxWindowSide);
  w.on_canvas.h = f.required_integer("height", 1, kMaxWindowSide);
  w.z = f.integer("z", -kMaxWindowId, kMaxWindowId, 0);
  const std::vector<std::string_view> fits = fits_of(w.source);
  if (f.has("fit") && fits.empty())
    f.fail("fit", fmt::format("a {} window frames itself: it takes no fit", w.source));
  if (!fits.empty()) w.fit = std::string(fits[static_cast<std::size_t>(f.choice("fit", fits, 0))]);
  return w;
}

std::uint32_t read_background(const TomlFields& top) {
  return static_cast<std::uint32_t>(top.integer("background", 0, 0xFFFFFF, 0));
}

// Desktops, counted as the coordinator connects to them: one per address and password file.
void check_desktops(const Session& session, const toml::array& list, const TomlSource& source) {
  std::vector<std::pair<std::filesystem::path, std::filesystem::path>> desktops;
  for (std::size_t i = 0; i < session.windows.size(); ++i) {
    const SessionWindow& w = session.windows[i];
    const auto desktop = std::pair{w.content, w.password_file};
    if (w.source != "vnc" || std::find(desktops.begin(), desktops.end(), desktop) != desktops.end())
      continue;
    desktops.push_back(desktop);
    if (desktops.size() > static_cast<std::size_t>(kMaxSessionDesktops))
      source.fail(*list.get(i), fmt::format("window[{}].content", i),
                  fmt::format("a {}th desktop, more than a session may show ({})", desktops.size(),
                              kMaxSessionDesktops));
  }
}

}  // namespace

Session parse_session(std::string_view toml_text, const std::filesystem::path& path_for_messages) {
  const TomlSource source{path_for_messages.string()};
  const toml::table doc = parse_toml(toml_text, source);
  const TomlFields top(doc, "", source, {"background", "shares", "window"});
  Session session;
  session.source = path_for_messages;
  session.background = read_background(top);
  const toml::array* list = top.array("window");
  if (!list || list->empty()) source.fail(0, "window", "the session has no windows ([[window]])");
  if (list->size() > static_cast<std::size_t>(kMaxWindows)) {
    source.fail(
        *list->get(static_cast<std::size_t>(kMaxWindows)), "window",
        fmt::format("{} windows, more than a session may have ({})", list->size(), kMaxWindows));
  }
  for (std::size_t i = 0; i < list->size(); ++i) {
    const std::string name = fmt::format("window[{}]", i);
    const toml::node& node = *list->get(i);
    if (!node.is_table())
      source.fail(node, name, fmt::format("must be a table, got {}", type_name(node)));
    const TomlFields f(
        *node.as_table(), name, source,
        {"id", "source", "content", "password_file", "x", "y", "width", "height", "z", "fit"});
    SessionWindow w = read_window(f, path_for_messages.parent_path());
    w.id = f.integer("id", 0, kMaxWindowId, static_cast<int>(i));
    for (std::size_t j = 0; j < session.windows.size(); ++j) {
      if (session.windows[j].id == w.id)
        f.fail("id", fmt::format("{} is already the id of window[{}]", w.id, j));
    }
    session.windows.push_back(std::move(w));
  }
  check_desktops(session, *list, source);
  session.shares = static_cast<int>(top.integer("shares", 0, kMaxSessionShares, 0));
  if (static_cast<int>(list->size()) + session.shares > kMaxWindows)
    top.fail("shares", fmt::format("{} windows and {} shares, more windows than a session may have "
                                   "({})",
                                   list->size(), session.shares, kMaxWindows));
  if (session.shares > 0 && share_window_id(session, session.shares - 1) > kMaxWindowId)
    top.fail("shares",
             fmt::format("the shares' windows take the ids after the largest ({}), past {}",
                         share_window_id(session, 0) - 1, kMaxWindowId));
  sort_windows(session.windows);
  return session;
}

int share_window_id(const Session& session, int slot) {
  int largest = -1;
  for (const SessionWindow& w : session.windows) largest = std::max(largest, w.id);
  return largest + 1 + slot;
}

Session load_session(const std::filesystem::path& path) {
  return parse_session(read_toml_file(path, "a session file"), path);
}

void sort_windows(std::vector<SessionWindow>& windows) {
  std::stable_sort(windows.begin(), windows.end(),
                   [](const SessionWindow& a, const SessionWindow& b) { return a.z < b.z; });
}

}  // namespace l2
