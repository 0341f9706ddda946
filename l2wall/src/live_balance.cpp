#include "l2wall/live_balance.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <climits>
#include <numeric>
#include <optional>
#include <stdexcept>

#include "balance/control_messages.hpp"
#include "frame_ranges.hpp"
#include "l2wall/run_fault.hpp"
#include "run_stats.hpp"
#include "tilelayout/tile_layout.hpp"
#include "waiting_message.hpp"

namespace l2 {
namespace {

// Strips per layout are listed up to this many layouts.
constexpr std::size_t kStripsListed = 8;

}  // namespace

LiveBalance::LiveBalance(const Wall& wall, BalanceSettings settings, const TileLayout& start,
                         int frames)
    : balancer_(wall, settings),
      survive_(wall.balance.survive_host_loss),
      frames_(frames),
      pending_(start.pipeservers.size()),
      have_(start.pipeservers.size(), false),
      frame_layout_(1, 0),
      strips_(1, 0),
      first_frame_(1, 0),
      last_(layout_message(0, start)),
      lines_{encode(last_)},
      own_(start) {
  if (!balancer_.first_refused().empty())
    rejected_.push_back(fmt::format("frame 1: {}", balancer_.first_refused()));
}

int LiveBalance::layout_of(int frame) const {
  const int last = static_cast<int>(frame_layout_.size()) - 1;
  return frame_layout_[static_cast<std::size_t>(std::clamp(frame, 0, last))];
}

LayoutMessage LiveBalance::layout_for(int frame) const {
  // Frames between two changes have no line of their own: the change before them holds.
  for (int f = std::min(frame, static_cast<int>(lines_.size()) - 1); f >= 0; --f) {
    if (!lines_[static_cast<std::size_t>(f)].empty())
      return decode_layout(lines_[static_cast<std::size_t>(f)]);
  }
  return last_;
}

std::string LiveBalance::mode() const {
  return to_string(balancer_.settings().mode);
}

bool LiveBalance::switch_mode(std::string_view mode, int frame, std::string& why) {
  const auto* name = std::find(std::begin(kBalanceModeNames), std::end(kBalanceModeNames), mode);
  if (name == std::end(kBalanceModeNames)) {
    why = fmt::format("balance mode '{}': expected static, strips or kd", mode);
    return false;
  }
  try {
    balancer_.switch_mode(static_cast<BalanceMode>(name - std::begin(kBalanceModeNames)));
  } catch (const LayoutError& e) {
    why = e.what();
    return false;
  }
  switches_.push_back(fmt::format("balance: switched to {} at frame {}\n", mode, frame));
  return true;
}

bool LiveBalance::lose(int pipeserver, int delivered, const std::string& how, double seconds) {
  try {
    balancer_.lose_pipeserver(pipeserver);
  } catch (const std::invalid_argument&) {
    return false;  // no one left to take its tiles
  } catch (const LayoutError& e) {
    // Said once, at the loss: the others' framebuffers cannot hold its tiles.
    throw RunFault(fmt::format("{}, and the run cannot go on without it: {}", how, e.what()));
  }
  losses_.push_back({pipeserver, how, delivered, seconds, -1});
  return true;
}

bool LiveBalance::stale(int frame) const {
  return std::any_of(losses_.begin(), losses_.end(), [frame](const Loss& l) {
    return frame >= l.first_missing && (l.first_without < 0 || frame < l.first_without);
  });
}

void LiveBalance::serve(PipeserverSet& pipeservers) {
  // A lost pipeserver sends nothing more: the frame's times are in once the others' are.
  for (const int s : balancer_.lost()) have_[static_cast<std::size_t>(s)] = true;
  for (LivePipeserver& h : pipeservers.serving()) {
    if (!h.control) continue;
    const std::size_t i = static_cast<std::size_t>(h.pipeserver);
    while (!have_[i]) {
      std::optional<TimesMessage> m = waiting_message(
          *h.control, h.pipeserver, [](const std::string& line) { return decode_times(line); });
      if (!m) break;
      if (m->frame != next_times_ || m->pipeserver != h.pipeserver) {
        throw RunFault(
            fmt::format("pipeserver {}: TIMES for frame {} of pipeserver {} while frame {} "
                        "is due",
                        h.pipeserver, m->frame, m->pipeserver, next_times_));
      }
      pending_[i] = std::move(m->seconds);
      // Every pipeserver draws the same scene on the same canvas: one's batches are all's.
      if (batches_.empty()) batches_ = std::move(m->footprints);
      have_[i] = true;
    }
  }
  if (std::find(have_.begin(), have_.end(), false) != have_.end()) return;
  const int frame = next_times_++;
  std::fill(have_.begin(), have_.end(), false);
  if (frame + 1 < frames_) send_layout(pipeservers, frame + 1);
  batches_.clear();
}

// Frame 0 was rendered in the wall's plan, not in the balancer's first layout: frame 1 takes
// that layout, and from then on each frame's times move it.
void LiveBalance::send_layout(PipeserverSet& pipeservers, int frame) {
  if (frame > 1) {
    if (balancer_.lost().empty()) note_costs();
    try {
      const BalanceStep step = balancer_.next(pending_, batches_);
      most_batches_ = std::max(most_batches_, batches_.size());
      per_triangle_.push_back(step.per_triangle);
      if (!step.rejected.empty())
        rejected_.push_back(fmt::format("frame {}: {}", frame, step.rejected));
      if (step.resisted) {
        ++resisted_;
        best_resisted_ = std::min(best_resisted_, step.predicted_ratio);
      }
    } catch (const std::invalid_argument& e) {
      throw RunFault(fmt::format("balancing frame {}: {}", frame, e.what()));
    } catch (const LayoutError& e) {
      // Only with a pipeserver lost: the others cannot take its tiles, and its layout cannot stay.
      throw RunFault(fmt::format("{}, and the run cannot go on without it: {}",
                                 losses_.empty() ? "a pipeserver died" : losses_.back().how,
                                 e.what()));
    }
  }
  const TileLayout& layout = balancer_.layout();
  for (Loss& l : losses_) {
    if (l.first_without < 0 &&
        layout.pipeservers[static_cast<std::size_t>(l.pipeserver)].tiles.empty())
      l.first_without = frame;
  }
  LayoutMessage m = layout_message(frame, layout);
  const std::string line = encode(m);
  for (LivePipeserver& h : pipeservers.serving()) {
    try {
      if (h.control) h.control->send_line(line);
    } catch (const ControlError&) {
      // the pipeserver is gone: the run names it from its exit
    }
  }
  pipeservers.place_stamps(layout, frame);
  // Frames are sent in order, one each: the vectors by frame grow by this one.
  lines_.resize(static_cast<std::size_t>(frame));
  lines_.push_back(line);
  // A new layout when its tiles or their pipeservers differ from the last frame's.
  int id = layout_of(frame - 1);
  if (m.tiles != last_.tiles || m.pipeservers != last_.pipeservers) {
    id = static_cast<int>(strips_.size());
    strips_.push_back(0);
    first_frame_.push_back(frame);
    last_ = std::move(m);
  }
  frame_layout_.resize(static_cast<std::size_t>(frame), frame_layout_.back());
  frame_layout_.push_back(id);
}

// The last frame's times were measured on the balancer's layout: what it took against what the
// wall's own layout would have.
void LiveBalance::note_costs() {
  double slowest = 0, work = 0;
  for (const std::vector<double>& tiles : pending_) {
    const double pipeserver = std::accumulate(tiles.begin(), tiles.end(), 0.0);
    slowest = std::max(slowest, pipeserver);
    work += pipeserver;
  }
  const FramePrediction own = balancer_.predicted(own_, pending_, batches_);
  slowest_ms_.push_back(slowest * 1e3);
  own_ms_.push_back(own.slowest * 1e3);
  work_ms_.push_back(work * 1e3);
  own_work_ms_.push_back(own.work * 1e3);
}

std::string balance_paid_line(const std::vector<double>& slowest_ms,
                              const std::vector<double>& own_ms) {
  const std::optional<Spread> slowest = spread_of(slowest_ms), own = spread_of(own_ms);
  if (!slowest || !own || slowest->p50 <= 0) return {};
  const double gain = own->p50 / slowest->p50;
  // A few percent either way is within what one frame's render times move by.
  const char* verdict = gain >= 1.05 ? "paid" : gain <= 0.95 ? "lost" : "no gain";
  // Render time only: the summary's "limited by" line says whether it limits the frame rate.
  return fmt::format(
      "balance: {} in render time: the slowest pipeserver took {:.1f} ms a frame (median); the "
      "wall's own layout, {:.1f} ms at the same costs ({:.2f}x)\n",
      verdict, slowest->p50, own->p50, gain);
}

std::string balance_work_line(const std::vector<double>& work_ms,
                              const std::vector<double>& own_work_ms) {
  const std::optional<Spread> work = spread_of(work_ms), own = spread_of(own_work_ms);
  if (!work || !own || own->p50 <= 0) return {};
  const double more = work->p50 / own->p50;
  return fmt::format(
      "balance: render work {:.1f} ms a frame (median), the wall's own layout {:.1f} ms at the "
      "same costs ({:.2f}x the work){}\n",
      work->p50, own->p50, more,
      more > 1.05 ? "; where pipeservers share cores the work, not the slowest pipeserver, sets "
                    "the frame rate"
                  : "");
}

void LiveBalance::count_strips(const PipeserverSet& pipeservers,
                               const std::vector<std::uint64_t>& routed_by_pipeserver) {
  for (std::size_t i = 0; i < routed_by_pipeserver.size() && i < pipeservers.all().size(); ++i)
    strips_[static_cast<std::size_t>(layout_of(pipeservers.all()[i].accepted))] +=
        routed_by_pipeserver[i];
}

void LiveBalance::check_swap(const std::vector<int>& group_displays,
                             const PipeserverSet& pipeservers,
                             const std::function<int(const LivePipeserver&)>& frame_shown) {
  std::vector<int> shown;
  for (const LivePipeserver& h : pipeservers.serving()) {
    const int frame = frame_shown(h);
    if (frame == INT_MAX) continue;
    const int display = h.stamp(frame).display;
    if (std::find(group_displays.begin(), group_displays.end(), display) != group_displays.end())
      shown.push_back(frame);
  }
  if (shown.empty()) return;
  ++swaps_checked_;
  const int first = layout_of(shown.front());
  const bool mixed =
      std::any_of(shown.begin(), shown.end(), [&](int f) { return layout_of(f) != first; });
  mixed_swaps_ += mixed ? 1 : 0;
}

// How the tiles were priced: by the batches they touch (the pipeservers' footprints) as well
// as their pixels, or by pixels alone when no footprints came.
std::string LiveBalance::pricing() const {
  const std::optional<Spread> price = spread_of(per_triangle_);
  if (!price) return {};
  if (most_batches_ == 0) {
    return "balance: tiles priced by their pixels alone (the pipeservers reported no batches)\n";
  }
  return fmt::format(
      "balance: tiles priced by their pixels and the batches they touch ({} batches a frame at "
      "most), median {:.1f} ns a triangle a tile\n",
      most_batches_, price->p50 * 1e9);
}

std::string LiveBalance::summary(int shown) const {
  std::string s =
      fmt::format("balance {}: {} layouts", to_string(balancer_.settings().mode), strips_.size());
  s += fmt::format(" (from frames {})", frame_ranges(first_frame_));
  if (strips_uncounted_.empty()) {
    s += ", strips routed per layout:";
    // A layout a frame would list hundreds: then only the fewest and the most.
    if (strips_.size() <= kStripsListed) {
      for (const std::uint64_t n : strips_) s += fmt::format(" {}", n);
    } else {
      const auto [fewest, most] = std::minmax_element(strips_.begin(), strips_.end());
      s += fmt::format(" {} to {}", *fewest, *most);
    }
  } else {
    s += fmt::format("; strips routed per layout not counted: {}", strips_uncounted_);
  }
  if (swaps_unchecked_.empty()) {
    s += fmt::format("\nbalance: {} of {} group swaps showed frames of two layouts\n", mixed_swaps_,
                     swaps_checked_);
  } else {
    s += fmt::format("\nbalance: group swaps not checked: {}\n", swaps_unchecked_);
  }
  for (const std::string& line : switches_) s += line;
  s += balance_paid_line(slowest_ms_, own_ms_);
  s += balance_work_line(work_ms_, own_work_ms_);
  s += pricing();
  if (resisted_ > 0) {
    s += fmt::format(
        "balance: {} new layout{} not taken (resistance {}): the best was predicted to take "
        "{:.2f} of the frame time\n",
        resisted_, resisted_ == 1 ? "" : "s", balancer_.settings().resistance, best_resisted_);
  }
  // The planner's reason is a long line, and on a tightly packed wall nearly every frame's plan
  // is refused for much the same one: the first in full, the rest counted.
  if (!rejected_.empty()) s += fmt::format("balance: not used, {}\n", rejected_.front());
  if (const std::size_t more = rejected_.size() > 1 ? rejected_.size() - 1 : 0; more > 0)
    s += fmt::format("balance: {} more layout{} refused, as above\n", more, more == 1 ? "" : "s");
  for (const Loss& l : losses_) s += loss_line(l, shown);
  return s;
}

// Only frames that reached the displays are stale: a run that ended early never rendered the rest.
std::string LiveBalance::loss_line(const Loss& l, int shown) const {
  const int shown_end = std::min(shown, frames_);
  const bool moved = l.first_without >= 0 && l.first_without < shown_end;
  const int end = moved ? l.first_without : shown_end;
  std::vector<int> stale, late;
  for (int f = l.first_missing; f < end; ++f) {
    stale.push_back(f);
    if (std::find(late_.begin(), late_.end(), f) != late_.end()) late.push_back(f);
  }
  std::string s = fmt::format("balance: lost {}, {:.2f} s into the run; ", l.how, l.seconds);
  s += moved ? fmt::format("its tiles went to the others from frame {}", l.first_without)
             : std::string("the run ended before a layout without it");
  s += fmt::format("; {} frame{} stale (shown incomplete or late)", stale.size(),
                   stale.size() == 1 ? "" : "s");
  if (!stale.empty()) s += ": " + frame_ranges(stale);
  if (!late.empty()) s += fmt::format(" (late: {})", frame_ranges(late));
  return s + "\n";
}

std::string LiveBalance::layouts() const {
  std::string text;
  for (const std::string& line : lines_) text += line + '\n';
  return text;
}

}  // namespace l2
