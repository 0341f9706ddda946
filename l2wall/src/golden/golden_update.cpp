#include "golden_update.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <optional>
#include <ostream>
#include <sstream>

#include "golden_rendered.hpp"
#include "image/png_io.hpp"

namespace l2 {

namespace {

// An entry's new images, waiting until every entry asked for has been produced and checked.
struct Pending {
  std::size_t entry = 0;  // index in the manifest
  std::vector<int> ids;
  std::vector<RgbImage> images;
  std::vector<bool> changed;  // per display: no golden yet, or different pixels
  int changed_count() const {
    return static_cast<int>(std::count(changed.begin(), changed.end(), true));
  }
};

// Both paths identical and the reference within tolerance: only then are the images worth
// keeping. Returns the reasons they are not.
std::vector<std::string> soundness_problems(const GoldenEntry& e, const EntryDisplays& shown) {
  std::vector<std::string> problems;
  const auto add = [&](const std::string& what, const SetComparison& c) {
    for (std::size_t i = 0; i < shown.ids.size(); ++i) {
      if (c.displays[i].identical()) continue;
      problems.push_back(fmt::format("{} display {}: {}: {}", e.name, shown.ids[i], what,
                                     describe_diff(c.displays[i])));
    }
  };
  if (!shown.vizserver.empty()) {
    const SetComparison c = compare_sets(shown.emulator, shown.vizserver, {});
    if (!c.passed) add("vizserver vs emulator", c);
  }
  const SetComparison r = compare_sets(shown.reference, shown.emulator, e.tolerance);
  if (!r.passed) {
    add("emulator vs " + shown.reference_name, r);
    problems.push_back(fmt::format(
        "{}: {} of {} pixels differ from the {} ({} by more than one "
        "level), beyond the tolerance ({})",
        e.name, r.differing, r.pixels, shown.reference_name, r.beyond_one, e.tolerance.describe()));
  }
  return problems;
}

// Compares the new images with the golden ones; routing-only changes are described in
// `refusals`, with pictures of them in OUT/<entry>/.
Pending compare_with_goldens(std::size_t index, const GoldenEntry& e, EntryDisplays& shown,
                             const UpdateOptions& o, std::vector<std::string>& refusals) {
  Pending p{index, shown.ids, std::move(shown.emulator), {}};
  for (std::size_t i = 0; i < p.ids.size(); ++i) {
    const auto file = o.paths.image(e, p.ids[i]);
    if (!std::filesystem::exists(file)) {
      p.changed.push_back(true);  // a new golden changes nothing that was agreed
      continue;
    }
    const RgbImage old = read_png(file);
    const DisplayDiff d = compare_displays(old, p.images[i]);
    p.changed.push_back(!d.identical());
    if (d.identical() || e.kind != GoldenKind::RoutingOnly) continue;
    const auto dir = o.out / e.name;
    const auto base = fmt::format("display-{}", p.ids[i]);
    write_png(dir / (base + "-new.png"), p.images[i]);
    write_png(dir / (base + "-diff.png"), highlight_differences(old, p.images[i]));
    refusals.push_back(
        fmt::format("{} display {}: routing-only golden would change: {}; new "
                    "image and diff picture: {}, {}",
                    e.name, p.ids[i], describe_diff(d), (dir / (base + "-new.png")).string(),
                    (dir / (base + "-diff.png")).string()));
  }
  return p;
}

void write_text(const std::filesystem::path& file, const std::string& text) {
  const auto tmp = file.string() + ".tmp";
  {
    std::ofstream f(tmp, std::ios::binary);
    f << text;
    if (!f) throw GoldenError(tmp + ": cannot write");
  }
  std::filesystem::rename(tmp, file);
}

std::string read_text(const std::filesystem::path& file) {
  std::ifstream f(file, std::ios::binary);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

// The options of this update besides the folders, as the user gave them.
std::string update_options(const UpdateOptions& o) {
  std::string text;
  for (const std::string& e : o.entries) text += " --entry " + shell_word(e);
  return text + " --out " + shell_word(o.out.string());
}

}  // namespace

int run_golden_update(const UpdateOptions& o, std::ostream& out) {
  GoldenManifest manifest = load_manifest(o.paths.manifest());
  const std::vector<const GoldenEntry*> selected = select_entries(manifest, o.entries);
  std::optional<GlInfo> gl;
  std::vector<Pending> pending;
  std::vector<std::string> problems, refusals;
  for (std::size_t n = 0; n < selected.size(); ++n) {
    throw_if_stopped();
    const GoldenEntry& e = *selected[n];
    out << fmt::format("[{}/{}] {} ... ", n + 1, selected.size(), e.name) << std::flush;
    if (e.kind == GoldenKind::Rendered && !gl)
      gl = pipeserver_gl_info(o.tools.pipeserver_program, o.out);
    std::filesystem::remove_all(o.out / e.name);
    EntryDisplays shown;
    try {
      shown = produce_entry(e, o.paths, o.tools, o.out / e.name / "run");
    } catch (const GoldenStopped&) {
      out << "stopped\n";
      throw;  // not the entry's failure: the command's end (golden_command.cpp)
    } catch (const std::exception& ex) {
      out << "FAILED\n";
      problems.push_back(fmt::format("{}: {}", e.name, ex.what()));
      continue;
    }
    const auto found = soundness_problems(e, shown);
    problems.insert(problems.end(), found.begin(), found.end());
    const std::size_t refused_before = refusals.size();
    pending.push_back(compare_with_goldens(
        static_cast<std::size_t>(selected[n] - manifest.entries.data()), e, shown, o, refusals));
    out << fmt::format("{}; {} of {} displays change{}\n", found.empty() ? "sound" : "NOT SOUND",
                       pending.back().changed_count(), pending.back().ids.size(),
                       refusals.size() > refused_before ? " (routing-only!)" : "");
  }
  for (const std::string& p : problems) out << p << "\n";
  for (const std::string& r : refusals) out << r << "\n";
  if (!problems.empty()) {
    out << "golden update: nothing written: the entries above are not sound\n";
    return 1;
  }
  if (!refusals.empty() && !o.allow_routing_change) {
    out << "golden update: refused, nothing written: routing-only (test-pattern) golden images "
           "must never change; a change means strips are routed elsewhere. If the change is "
           "intended (the test pattern or a wall file changed), run `"
        << o.paths.command("update", update_options(o) + " --allow-routing-change") << "`\n";
    return 1;
  }
  int written = 0;
  for (const Pending& p : pending) {
    GoldenEntry& e = manifest.entries[p.entry];
    for (std::size_t i = 0; i < p.ids.size(); ++i) {
      if (!p.changed[i]) continue;
      write_png(o.paths.image(e, p.ids[i]), p.images[i]);
      ++written;
    }
    if (e.kind == GoldenKind::Rendered && (p.changed_count() > 0 || !same_renderer(e, *gl))) {
      e.mesa = gl->mesa_version();
      e.gl_version = gl->version;
      e.gl_renderer = gl->renderer;
    }
  }
  const std::string text = format_manifest(manifest);
  const bool manifest_changed = read_text(o.paths.manifest()) != text;
  if (manifest_changed) write_text(o.paths.manifest(), text);
  out << fmt::format("golden update: {} image{} written{}\n", written, written == 1 ? "" : "s",
                     manifest_changed ? ", manifest rewritten" : "");
  return 0;
}

}  // namespace l2
