// `lightning2_emu sequence`: folders of frames over time, one per input, through the emulator
// with the frame rules of spec §6; writes what every display shows at every refresh.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "commands.hpp"
#include "image/folders.hpp"
#include "image/png_io.hpp"
#include "lightning2_emu/frame_files.hpp"
#include "lightning2_emu/out_folder.hpp"
#include "lightning2_emu/report_json.hpp"
#include "sequence_show.hpp"

namespace l2 {
namespace {

// Removes the frame-<tttt>.png pictures an earlier run left in `folder`: a shorter run into the
// same --out left the longer run's later frames beside its own. Only files named as this
// command names them are touched.
void remove_old_frames(const std::filesystem::path& folder) {
  remove_earlier(
      folder,
      [](const std::filesystem::directory_entry& entry) {
        return entry.is_regular_file() &&
               numbered_name(entry.path().filename().string(), "frame-", ".png", 4);
      },
      "this frame of an earlier run");
}

// The frames of refresh t: a DVI link keeps scanning out the last framebuffer, so an input past
// its last file repeats it. Only the current frame of each input is held.
void take_frames(int t, const std::vector<std::vector<std::filesystem::path>>& inputs,
                 const Mesh& mesh, std::vector<RgbImage>& images, std::vector<InputFrame>& frames) {
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    const std::size_t k = std::min<std::size_t>(t, inputs[i].size() - 1);
    if (t > 0 && k != static_cast<std::size_t>(t)) continue;
    // Checked on the file's header: a picture larger than a board takes is never allocated.
    images[i] = read_scanned_frame(inputs[i][k], [&](int width, int height) {
      mesh.check_input(static_cast<int>(i), width, height, inputs[i][k].string());
    });
    frames[i] = InputFrame::of(images[i]);
  }
}

// Writes what every display shows during refresh t, and with a wall file the wall picture;
// counts the pictures in `written` as they are written. Returns the displays by id.
std::vector<const RgbImage*> write_refresh(const Setup& setup, const Emulator& emulator,
                                           const std::filesystem::path& out, int t, int& written) {
  std::vector<const RgbImage*> by_id(kMaxDisplays, nullptr);
  for (const DisplaySpec& d : setup.config.displays) {
    by_id[d.id] = &emulator.shown(d.id);
    write_png(out / fmt::format("display-{}", d.id) / fmt::format("frame-{:04}.png", t),
              emulator.shown(d.id));
    ++written;
  }
  if (setup.from_wall) {
    write_png(out / "wall" / fmt::format("frame-{:04}.png", t), compose_wall(setup, by_id));
  }
  return by_id;
}

// What OUT holds of this run when it stops part way: "the pictures of refreshes 0-4 and part of
// refresh 5", empty when nothing was written.
std::string pictures_held(int refreshes_written, int pictures_of_next) {
  std::vector<std::string> held;
  if (refreshes_written == 1) held.push_back("the pictures of refresh 0");
  if (refreshes_written > 1) {
    held.push_back(fmt::format("the pictures of refreshes 0-{}", refreshes_written - 1));
  }
  if (pictures_of_next > 0) held.push_back(fmt::format("part of refresh {}", refreshes_written));
  return fmt::format("{}", fmt::join(held, " and "));
}

}  // namespace

int run_sequence(const CommonOptions& o, int ticks, const ShowOptions& show) {
  const Setup setup = make_setup(o);
  const Mesh& mesh = setup.config.mesh;
  prepare_out(o.out);
  std::vector<std::vector<std::filesystem::path>> inputs;
  std::size_t longest = 0;
  for (const std::string& folder : o.inputs) {
    inputs.push_back(list_frames(folder));
    longest = std::max(longest, inputs.back().size());
  }
  // One refresh more than the longest input, so its last frame reaches the displays.
  if (ticks <= 0) ticks = static_cast<int>(longest) + 1;

  for (const DisplaySpec& d : setup.config.displays) {
    remove_old_frames(o.out / fmt::format("display-{}", d.id));
  }
  remove_old_frames(o.out / "wall");

  Emulator emulator(setup.config);
  std::unique_ptr<SequenceShow> screen;
  if (!show.mode.empty()) screen = std::make_unique<SequenceShow>(o, setup, show);
  std::vector<RgbImage> images(inputs.size());
  std::vector<InputFrame> frames(inputs.size());
  SequenceReport log;
  // Refreshes whose pictures are all written, and pictures of the refresh after them: when a
  // frame cannot be read or a picture written part way, the error says what OUT holds.
  int refreshes_written = 0, pictures_of_next = 0;
  try {
    for (int t = 0; t < ticks; ++t) {
      take_frames(t, inputs, mesh, images, frames);
      const Emulator::Tick& tick = emulator.tick(frames);
      log.add(tick);
      const auto by_id = write_refresh(setup, emulator, o.out, t, pictures_of_next);
      refreshes_written = t + 1;
      pictures_of_next = 0;
      if (screen && !screen->play(t, by_id)) break;  // q / Esc: the sequence ends here
    }
    log.write(o.out / "report.json", emulator.report());
  } catch (const std::runtime_error& e) {
    throw partly_written(e, o.out, pictures_held(refreshes_written, pictures_of_next),
                         "no report.json");
  }
  const RunReport& r = emulator.report();
  fmt::print(
      "{} refreshes of {} inputs: {} new, {} repeated, {} torn, {} idle frames ({} predicted "
      "from their input's last layout, {} of them found different and parsed); wrote {}\n",
      r.ticks, inputs.size(), r.frames(FrameKind::New), r.frames(FrameKind::Repeat),
      r.frames(FrameKind::Torn), r.frames(FrameKind::Idle), r.frames_predicted,
      r.predictions_missed, o.out.string());
  return 0;
}

}  // namespace l2
