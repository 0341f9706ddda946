#include "golden_check.hpp"

#include <fmt/format.h>

#include <chrono>
#include <optional>
#include <ostream>
#include <sstream>

#include "golden_rendered.hpp"
#include "image/png_io.hpp"
#include "tilelayout/planner.hpp"
#include "tilelayout/wall_file.hpp"

namespace l2 {

namespace {

// One comparison of an entry: what is compared with what, and the files a mismatch writes.
struct Comparison {
  std::string what;             // "emulator vs golden image"
  std::string actual_suffix;    // display-<id><suffix>.png: the image found
  std::string expected_suffix;  // ... the image expected, when it is not in the golden folder
  std::string diff_suffix;
};

enum class EntryResult { Passed, Failed, NotRun };

class EntryCheck {
 public:
  EntryCheck(const GoldenEntry& entry, const CheckOptions& options, std::ostream& out)
      : entry_(entry), out_(out), dir_(options.out / entry.name) {}

  EntryResult result() const { return result_; }

  // The check itself could not be made (an input, a tool or a golden image is missing): not a
  // mismatch, which is what exit status 1 tells.
  void could_not_run(const std::string& message) {
    out_ << entry_.name << ": could not be checked: " << message << "\n";
    result_ = EntryResult::NotRun;
  }

  // Compares and, for every display that differs when the set fails, writes the pictures and
  // prints the summary line. Within the tolerance but not identical: one line with the counts.
  void compare(const Comparison& c, const std::vector<int>& ids,
               const std::vector<RgbImage>& expected, const std::vector<RgbImage>& actual,
               const Tolerance& tolerance) {
    const SetComparison result = compare_sets(expected, actual, tolerance);
    if (result.passed) {
      if (result.differing > 0) {
        out_ << fmt::format(
            "{}: {}: {} of {} pixels differ ({} by more than one level), within "
            "the tolerance ({})\n",
            entry_.name, c.what, result.differing, result.pixels, result.beyond_one,
            tolerance.describe());
      }
      return;
    }
    if (result_ == EntryResult::Passed) result_ = EntryResult::Failed;
    for (std::size_t i = 0; i < ids.size(); ++i) {
      const DisplayDiff& d = result.displays[i];
      if (d.identical()) continue;
      const std::string base = fmt::format("display-{}", ids[i]);
      std::vector<std::string> written{write(base + c.actual_suffix, actual[i])};
      if (!c.expected_suffix.empty())
        written.push_back(write(base + c.expected_suffix, expected[i]));
      written.push_back(write(base + c.diff_suffix, highlight_differences(expected[i], actual[i])));
      out_ << fmt::format("{} display {}: {}: {}; wrote {}\n", entry_.name, ids[i], c.what,
                          describe(d, expected[i], actual[i]), fmt::join(written, ", "));
    }
    if (!tolerance.exact) {
      out_ << fmt::format(
          "{}: {}: {} of {} pixels differ ({} by more than one level), beyond the "
          "tolerance ({})\n",
          entry_.name, c.what, result.differing, result.pixels, result.beyond_one,
          tolerance.describe());
    }
  }

  std::string write(const std::string& name, const RgbImage& image) const {
    const auto path = dir_ / (name + ".png");
    write_png(path, image);
    return path.string();
  }

 private:
  static std::string describe(const DisplayDiff& d, const RgbImage& expected,
                              const RgbImage& actual) {
    if (!d.size_differs) return describe_diff(d);
    return fmt::format("the size differs: expected {}x{}, got {}x{}", expected.width(),
                       expected.height(), actual.width(), actual.height());
  }

  const GoldenEntry& entry_;
  std::ostream& out_;
  std::filesystem::path dir_;
  EntryResult result_ = EntryResult::Passed;
};

const Comparison kAgainstGolden{"emulator vs golden image", "-actual", "", "-diff"};
const Comparison kVizserver{"vizserver vs emulator", "-vizserver", "-actual", "-vizserver-diff"};

std::vector<RgbImage> load_goldens(const GoldenPaths& paths, const GoldenEntry& entry,
                                   const std::vector<int>& ids, EntryCheck& check) {
  std::vector<RgbImage> goldens;
  for (const int id : ids) {
    const auto file = paths.image(entry, id);
    if (!std::filesystem::exists(file)) {
      check.could_not_run(
          fmt::format("golden image {} is missing (make it with `{}`)", file.string(),
                      paths.command("update", " --entry " + shell_word(entry.name))));
      return {};
    }
    goldens.push_back(read_png(file));
  }
  return goldens;
}

// The tolerance for the golden comparison: exact, unless a rendered entry's images come from
// another GL implementation, whose rounding may differ (said in the output).
Tolerance golden_tolerance(const GoldenEntry& entry, const GlInfo& gl, std::ostream& out) {
  if (entry.kind == GoldenKind::RoutingOnly || same_renderer(entry, gl)) return {};
  out << fmt::format(
      "{}: golden images made with {}, this is {}: compared within the tolerance ({}), "
      "not exactly\n",
      entry.name, describe_renderer(entry.mesa, entry.gl_renderer),
      describe_renderer(gl.mesa_version(), gl.renderer), entry.tolerance.describe());
  return entry.tolerance;
}

EntryDisplays produce(const GoldenEntry& entry, const CheckOptions& o, std::ostream& out) {
  if (o.inputs.empty()) return produce_entry(entry, o.paths, o.tools, o.out / entry.name / "run");
  const TileLayout layout = plan_layout(load_wall(o.paths.root / entry.wall));
  out << fmt::format("{}: frames from {}: DVI path only, against the golden images\n", entry.name,
                     o.inputs.string());
  return produce_from_captured(layout, o.inputs);
}

void report_input_errors(const GoldenEntry& entry, const StripErrorCounts& e, std::ostream& out) {
  if (e.total() == 0) return;
  out << fmt::format(
      "{}: {} strip errors on the inputs (spec §3): {} check, {} EXT, {} zero width, {} "
      "truncated, {} to missing displays, {} clipped\n",
      entry.name, e.total(), e.check_errors, e.ext_unsupported, e.zero_width, e.truncations,
      e.missing_display, e.clips);
}

// Pixels that differ from the golden images only because the frame stamps moved with a new
// tiling are left out of the comparison, and said so: they are the run's bookkeeping, not the
// picture.
void set_aside_stamps(const GoldenEntry& entry, const CheckOptions& o,
                      const std::vector<RgbImage>& goldens, std::vector<RgbImage>& emulator,
                      std::ostream& out) {
  const int pipeservers =
      static_cast<int>(plan_layout(load_wall(o.paths.root / entry.wall)).pipeservers.size());
  const int moved = set_aside_moved_stamps(entry.frame, pipeservers, goldens, emulator);
  if (moved == 0) return;
  out << fmt::format(
      "{}: {} pixel{} differ{} from the golden images only by frame {}'s stamp (the first pixel "
      "of each pipeserver's first tile, moved by another tiling): left out of the comparison\n",
      entry.name, moved, moved == 1 ? "" : "s", moved == 1 ? "s" : "", entry.frame);
}

// `gl` is asked for (pipeserver --gl-info) the first time a rendered entry needs it.
EntryResult check_entry(const GoldenEntry& entry, const CheckOptions& o, std::optional<GlInfo>& gl,
                        std::ostream& out) {
  EntryCheck check(entry, o, out);
  std::filesystem::remove_all(o.out / entry.name);
  try {
    const EntryDisplays shown = produce(entry, o, out);
    report_input_errors(entry, shown.input_errors, out);
    if (o.write_actual) {
      for (std::size_t i = 0; i < shown.ids.size(); ++i) {
        check.write(fmt::format("display-{}-actual", shown.ids[i]), shown.emulator[i]);
      }
    }
    const std::vector<RgbImage> goldens = load_goldens(o.paths, entry, shown.ids, check);
    if (!goldens.empty()) {
      if (entry.kind == GoldenKind::Rendered && !gl)
        gl = pipeserver_gl_info(o.tools.pipeserver_program, o.out);
      const Tolerance t = gl ? golden_tolerance(entry, *gl, out) : Tolerance{};
      std::vector<RgbImage> emulator = shown.emulator;
      if (entry.kind == GoldenKind::Rendered) set_aside_stamps(entry, o, goldens, emulator, out);
      check.compare(kAgainstGolden, shown.ids, goldens, emulator, t);
    }
    if (!shown.vizserver.empty()) {
      check.compare(kVizserver, shown.ids, shown.emulator, shown.vizserver, {});
    }
    if (!shown.reference.empty()) {
      const Comparison against_reference{"emulator vs " + shown.reference_name, "-actual",
                                         "-reference", "-reference-diff"};
      check.compare(against_reference, shown.ids, shown.reference, shown.emulator, entry.tolerance);
    }
  } catch (const GoldenStopped&) {
    out << "stopped\n";
    throw;  // not the entry's failure: the command's end (golden_command.cpp)
  } catch (const std::exception& e) {
    check.could_not_run(e.what());
  }
  return check.result();
}

std::string describe_entry(const GoldenEntry& e, bool from_inputs) {
  return fmt::format("{} ({}, {} frame {}, {})", e.name, e.wall, e.scene, e.frame,
                     from_inputs   ? "captured frames"
                     : e.vizserver ? "dvi+vizserver"
                                   : "dvi");
}

}  // namespace

int run_golden_check(const CheckOptions& o, std::ostream& out) {
  const GoldenManifest manifest = load_manifest(o.paths.manifest());
  const std::vector<const GoldenEntry*> entries = select_entries(manifest, o.entries);
  if (!o.inputs.empty()) {
    if (o.entries.size() != 1) {
      throw GoldenError("--inputs: name the one entry the frames belong to with --entry");
    }
    if (entries.front()->kind != GoldenKind::RoutingOnly) {
      throw GoldenError(fmt::format(
          "--inputs: {} is a rendered entry; captured frames are checked against routing-only "
          "(test-pattern) entries, whose images do not depend on any renderer",
          entries.front()->name));
    }
  }
  int failed = 0, not_run = 0;
  std::string failed_entries;  // " --entry NAME" for each, for the update command
  bool routing_failed = false;
  std::optional<GlInfo> gl;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    throw_if_stopped();
    const GoldenEntry& e = *entries[i];
    // One line per entry, finished when its check is; what the check found follows it.
    out << fmt::format("[{}/{}] {} ... ", i + 1, entries.size(),
                       describe_entry(e, !o.inputs.empty()))
        << std::flush;
    const auto t0 = std::chrono::steady_clock::now();
    std::ostringstream details;
    const EntryResult result = check_entry(e, o, gl, details);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const char* said = result == EntryResult::Passed   ? "ok"
                       : result == EntryResult::Failed ? "FAILED"
                                                       : "could not run";
    out << fmt::format("{} ({:.1f} s)\n", said, s) << details.str() << std::flush;
    failed += result == EntryResult::Failed;
    if (result == EntryResult::Failed) failed_entries += " --entry " + shell_word(e.name);
    // The update refuses to change a routing-only image without it: the hint must work as given.
    routing_failed =
        routing_failed || (result == EntryResult::Failed && e.kind == GoldenKind::RoutingOnly);
    not_run += result == EntryResult::NotRun;
  }
  if (failed == 0 && not_run == 0) {
    out << fmt::format("golden check: all {} entries pass\n", entries.size());
    return 0;
  }
  if (failed > 0) {
    out << fmt::format(
        "golden check: {} of {} entries FAILED; actual images and diff pictures in "
        "{}\n",
        failed, entries.size(), o.out.string());
    out << fmt::format(
        "golden check: if the change is intended, make them the golden images: `{}`\n",
        o.paths.command("update",
                        failed_entries + (routing_failed ? " --allow-routing-change" : "")));
  }
  if (not_run > 0) {
    // Exit 2 even beside mismatches: a check that was not made is not a pass or a fail.
    out << fmt::format("golden check: {} of {} entries could not be checked\n", not_run,
                       entries.size());
    return 2;
  }
  return 1;
}

}  // namespace l2
