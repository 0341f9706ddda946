// Balancing in a live run (`[balance]`, `l2wall run --balance`): the coordinator side of the
// control channel. Each pipeserver sends its tiles' times after every frame (TIMES); once every
// pipeserver's times of frame k are in, the Balancer plans frame k+1 and the same LAYOUT goes to
// every pipeserver, so all switch together. It also says where each frame's stamps are (the layout
// moves them) and counts, from the stamps the run reads, the strips routed in each layout and the
// group swaps that showed frames of two layouts at once.
//
// With --survive-host-loss a pipeserver that dies is lost, not the end of the run: the next layout
// is planned over the others (the Balancer), the frames whose layouts still gave it tiles are
// stale (shown without its part, some of them late), and the summary says so.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "balance/balancer.hpp"
#include "balance/control_messages.hpp"
#include "l2wall/pipeserver_set.hpp"

namespace l2 {

// The summary's answer to whether balancing paid, from each frame's slowest pipeserver's render
// time on the balanced layout and the wall's own layout's predicted at the same tile costs (ms,
// frame by frame), in medians: "balance: paid in render time: the slowest pipeserver took 11.0
// ms a frame (median); the wall's own layout, 18.0 ms at the same costs (1.64x)" (or "lost",
// "no gain" within 5 %); empty for no frames.
std::string balance_paid_line(const std::vector<double>& slowest_ms,
                              const std::vector<double>& own_ms);
// The same for the frame's render work, every pipeserver's render time summed: "balance: render
// work 70.1 ms a frame (median), the wall's own layout 41.0 ms at the same costs (1.71x the
// work); where pipeservers share cores the work, not the slowest pipeserver, sets the frame rate"
// (the clause only where balancing added work, by more than 5 %); empty for no frames.
std::string balance_work_line(const std::vector<double>& work_ms,
                              const std::vector<double>& own_work_ms);

class LiveBalance {
 public:
  // Frame 0 is rendered in `start` (the wall's plan, as every pipeserver starts).
  LiveBalance(const Wall& wall, BalanceSettings settings, const TileLayout& start, int frames);

  // Reads every TIMES line waiting, and sends LAYOUT k+1 once frame k's times are all in.
  // Throws RunFault for a line that is not the expected TIMES.
  void serve(PipeserverSet& pipeservers);
  // After a refresh: counts the strips each pipeserver's new frame routed, by that frame's layout.
  void count_strips(const PipeserverSet& pipeservers,
                    const std::vector<std::uint64_t>& routed_by_pipeserver);
  // The lead path cannot count strips (`why`): the summary says so instead of counts.
  void strips_not_counted(std::string why) { strips_uncounted_ = std::move(why); }
  // A path whose swaps cannot show two layouts says why it does not check them.
  void swaps_not_checked(std::string why) { swaps_unchecked_ = std::move(why); }
  // After a swap group swapped: whether the frames its displays (`group_displays`) now show
  // share one layout. `frame_shown(h)`: the frame pipeserver h's stamp says the displays show of it
  // (INT_MAX: not known); a pipeserver counts when that frame's stamp is on one of the group's.
  void check_swap(const std::vector<int>& group_displays, const PipeserverSet& pipeservers,
                  const std::function<int(const LivePipeserver&)>& frame_shown);

  // Whether a pipeserver that dies is survived (--survive-host-loss, [balance] survive_host_loss).
  bool survives_losses() const { return survive_; }
  // Pipeserver `pipeserver` died (`how`: "pipeserver 1 (pid 4242) killed by signal 9 (Killed) while
  // rendering frame 57") having delivered frames 0..delivered-1, `seconds` into the run: the
  // layouts from the next one on give it nothing. False when it was the last one rendering.
  bool lose(int pipeserver, int delivered, const std::string& how, double seconds);
  // Whether frame `frame` is rendered in a layout that gives a lost pipeserver tiles it never
  // delivered: shown incomplete, and maybe late (its pipeserver's death noticed after the others'
  // part came in).
  bool stale(int frame) const;
  // A stale frame that reached the displays later than one refresh after its last input.
  void note_late(int frame) { late_.push_back(frame); }

  // The layout frame `frame` is rendered in (0: the start, then one more each change).
  int layout_of(int frame) const;
  // Its tiles and their pipeservers, as the LAYOUT line sent for it said (the control page draws
  // them); a frame not planned yet: the last layout sent.
  LayoutMessage layout_for(int frame) const;

  // The mode the next layouts are cut by, and a switch to another from the next frame planned
  // on (the control page): false, with the reason in `why`, when the wall cannot take it.
  std::string mode() const;
  bool switch_mode(std::string_view mode, int frame, std::string& why);
  std::uint64_t mixed_swaps() const { return mixed_swaps_; }
  // Summary lines: the mode, the layouts used, strips per layout, mixed swaps, how tiles were
  // priced (pixels, and the batches they touch), the first rejected
  // plan in full and how many more were rejected, the pipeservers lost and the frames stale
  // among those shown (frames 0..shown-1 reached the displays).
  std::string summary(int shown) const;
  // OUT/layouts.txt's text: frame k's LAYOUT line on line k+1, as every pipeserver got it (frame
  // 0: the wall's plan, which the pipeservers start in).
  std::string layouts() const;

 private:
  void send_layout(PipeserverSet& pipeservers, int frame);
  void note_costs();
  std::string pricing() const;

  struct Loss {
    int pipeserver = 0;
    std::string how;
    int first_missing = 0;  // the first frame it did not deliver
    double seconds = 0;
    int first_without = -1;  // the first frame whose layout gives it no tile; -1: none yet
  };
  // The summary's line of a loss, its stale frames among the `shown`.
  std::string loss_line(const Loss& l, int shown) const;

  Balancer balancer_;
  bool survive_ = false;
  std::vector<Loss> losses_;
  std::vector<int> late_;  // stale frames shown late
  int frames_;
  int next_times_ = 0;                        // the frame whose times are being collected
  std::vector<std::vector<double>> pending_;  // by pipeserver, that frame's times
  Footprints batches_;  // that frame's batch footprints, from the first pipeserver to send them
  std::size_t most_batches_ = 0;       // the most footprints a frame brought
  std::vector<double> per_triangle_;   // each step's fitted price of a batch's triangle
  std::vector<bool> have_;             // by pipeserver, whether they are in
  std::vector<int> frame_layout_;      // by frame sent so far; later frames are in the last layout
  std::vector<std::uint64_t> strips_;  // by layout
  std::vector<int> first_frame_;       // by layout
  std::uint64_t mixed_swaps_ = 0;
  std::uint64_t swaps_checked_ = 0;
  std::vector<std::string> rejected_;
  int resisted_ = 0;                   // new layouts not taken: they would not pay (resistance)
  double best_resisted_ = 1;           // the lowest predicted frame time ratio among them
  std::string strips_uncounted_;       // why the strips are not counted; empty: they are
  std::string swaps_unchecked_;        // why the group swaps are not checked; empty: they are
  LayoutMessage last_;                 // the last layout's tiles and pipeservers
  std::vector<std::string> lines_;     // by frame sent so far, the LAYOUT line
  std::vector<std::string> switches_;  // the mode switches, for the summary
  TileLayout own_;                     // the wall's own layout, frame 0's
  std::vector<double> slowest_ms_;     // by frame measured on a balanced layout, none lost: the
  std::vector<double> own_ms_;         // slowest render, and the own layout's predicted;
  std::vector<double> work_ms_;        // every render summed, and the own layout's predicted
  std::vector<double> own_work_ms_;
};

}  // namespace l2
