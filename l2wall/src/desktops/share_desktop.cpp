// A screen shared from a control page's browser (control_page/README.md): its frames arrive on
// the HTTP server's threads as JPEG, decoded there into the share inbox; this source takes the
// newest into the live desktop when the run takes updates, so a frame is whole or not there.
// A share that stalls keeps its last frame: nothing new is taken, nothing is damaged.
#include <fmt/format.h>

#include "control_page/share_inbox.hpp"
#include "desktop_source.hpp"

namespace l2 {
namespace {

class ShareDesktop final : public DesktopSource {
 public:
  ShareDesktop(std::shared_ptr<ShareInbox> inbox, int window, int width, int height)
      : inbox_(std::move(inbox)), window_(window), width_(width), height_(height) {}

  int width() const override { return width_; }
  int height() const override { return height_; }

  // Never waits: the run's frame loop takes frames between its own, and a browser's next frame
  // is due in the time of a few of the wall's.
  void take_updates(DesktopFrames& frames, std::chrono::milliseconds /*wait*/) override {
    std::optional<RgbImage> frame = inbox_->take(window_);
    if (!frame) return;
    if (frame->width() != frames.width() || frame->height() != frames.height())
      throw DesktopError(fmt::format("share of window {}: a frame of {}x{} for a share of {}x{}",
                                     window_, frame->width(), frame->height(), frames.width(),
                                     frames.height()));
    frames.live() = std::move(*frame);
    frames.damaged({0, 0, width_, height_});
  }

 private:
  std::shared_ptr<ShareInbox> inbox_;
  int window_, width_, height_;
};

}  // namespace

std::unique_ptr<DesktopSource> share_source(std::shared_ptr<ShareInbox> inbox, int window,
                                            int width, int height) {
  return std::make_unique<ShareDesktop>(std::move(inbox), window, width, height);
}

}  // namespace l2
