#include "live_desktop.hpp"

#include <fmt/format.h>

#include <chrono>

#include "balance/control_messages.hpp"
#include "l2wall/run_fault.hpp"

namespace l2 {
namespace {

constexpr std::chrono::milliseconds kFirstUpdate{10000};

}  // namespace

LiveDesktop::LiveDesktop(std::unique_ptr<DesktopSource> source, const TileLayout& layout)
    : source_(std::move(source)),
      frames_(source_->width(), source_->height(), static_cast<int>(layout.pipeservers.size())) {
  for (const PipeserverPlan& p : layout.pipeservers) {
    std::vector<Rect>& rects = tiles_.emplace_back();
    for (const PackedTile& t : p.tiles) rects.push_back(t.tile.on_canvas);
  }
  // Frame 0 shows the desktop, not the black before the server's first update.
  const auto give_up = std::chrono::steady_clock::now() + kFirstUpdate;
  while (!frames_.changed() && std::chrono::steady_clock::now() < give_up)
    source_->take_updates(frames_, std::chrono::milliseconds(50));
  if (!frames_.changed())
    throw DesktopError(
        fmt::format("vnc: the server sent no picture within {} s",
                    std::chrono::duration_cast<std::chrono::seconds>(kFirstUpdate).count()));
}

void LiveDesktop::take_updates() {
  try {
    source_->take_updates(frames_, std::chrono::milliseconds(0));
  } catch (const DesktopError& e) {
    throw RunFault(e.what());
  }
}

void LiveDesktop::serve(PipeserverSet& pipeservers) {
  take_updates();
  for (LivePipeserver& h : pipeservers.serving()) {
    if (!h.windows) continue;
    for (;;) {
      std::optional<std::string> line;
      try {
        line = h.windows->receive_line(std::chrono::milliseconds(0));
      } catch (const ControlError&) {
        break;  // the pipeserver is gone: the run names it from its exit
      }
      if (!line) break;
      std::vector<std::string> answer;
      try {
        const WantMessage m = decode_want(*line);
        if (m.pipeserver != h.pipeserver)
          throw ControlError(fmt::format("WANT of pipeserver {}", m.pipeserver));
        answer = frames_.answer(h.pipeserver, m.frame,
                                tiles_.at(static_cast<std::size_t>(h.pipeserver)));
      } catch (const std::runtime_error& e) {
        throw RunFault(fmt::format("pipeserver {}: {}", h.pipeserver, e.what()));
      }
      try {
        for (const std::string& a : answer) h.windows->send_line(a);
      } catch (const ControlError&) {
        break;
      }
    }
  }
}

std::string LiveDesktop::summary() const {
  return fmt::format("vnc: desktop {}x{}\n", frames_.width(), frames_.height());
}

}  // namespace l2
