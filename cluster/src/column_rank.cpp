#include "column_rank.hpp"

#include <algorithm>
#include <cstdio>
#include <memory>
#include <vector>

#include "cluster/mpi_dvi_link.hpp"
#include "cluster/mpi_wire.hpp"
#include "frame_stamp.hpp"
#include "lightning2_emu/router.hpp"
#include "lightning2_emu/swap_group.hpp"

namespace l2 {
namespace {

using mpi_wire::Reader;
using mpi_wire::Record;

struct ColumnInput {
  int server = 0;
  std::unique_ptr<MpiDviReceiver> receiver;
  int stamp = -1;  // the frame stamp of the frame taken in
};

class Column {
 public:
  Column(const TileLayout& layout, const RankMap& map, int column, int threads)
      : layout_(layout),
        map_(map),
        column_(column),
        pool_(threads),
        router_(mesh(layout.wall), specs(layout.wall, map.displays_of_column[column]), pool_),
        frames_(static_cast<std::size_t>(map.mesh_inputs)),
        back_frame_(static_cast<std::size_t>(router_.display_count()), -1),
        done_frame_(back_frame_),
        shown_frame_(back_frame_) {
    // Every refresh's layout is parsed: the prediction's second choice (router.hpp) would be a
    // second round trip to the coordinator.
    router_.predict_layouts(false);
    for (const int s : map.servers_of_column[column]) {
      const ServerPlan& plan = layout.servers[static_cast<std::size_t>(s)];
      inputs_.push_back({s, std::make_unique<MpiDviReceiver>(map.pipeserver_rank(s), plan.fb_width,
                                                             plan.fb_height)});
    }
    std::vector<DisplaySpec> all;
    for (const Display& d : layout.wall.displays)
      all.push_back({d.id, d.width, d.height, d.swap_group});
    for (const SwapGroup& g : make_swap_groups(all)) {
      std::vector<int>& own = group_indices_.emplace_back();
      for (const int id : g.displays) {
        if (const int index = router_.index_of_display(id); index >= 0) own.push_back(index);
      }
    }
  }

  void run() {
    for (;;) {
      const Record command = mpi_wire::receive(RankMap::kCoordinator, mpi_wire::kCommand);
      Reader in(command);
      switch (in.next()) {
        case mpi_wire::kTick:
          tick(in);
          break;
        case mpi_wire::kRoute:
          route(in);
          break;
        case mpi_wire::kFetch:
          send_pictures();
          break;
        case mpi_wire::kEnd:
          return;
        default:
          throw std::runtime_error("unknown command from the coordinator");
      }
    }
  }

 private:
  static Mesh mesh(const Wall& wall) {
    return Mesh::fit(wall.server_count, static_cast<int>(wall.displays.size()),
                     {wall.board_max_width, wall.board_max_height});
  }

  static std::vector<DisplaySpec> specs(const Wall& wall, const std::vector<int>& ids) {
    std::vector<DisplaySpec> out;
    for (const Display& d : wall.displays) {
      if (std::find(ids.begin(), ids.end(), d.id) != ids.end())
        out.push_back({d.id, d.width, d.height, d.swap_group});
    }
    return out;
  }

  // [kTick, refresh, n, swapped group indices..., n, sequence per server...]
  void tick(Reader& in) {
    const std::int64_t refresh = in.next();
    for (int n = in.next_int(); n > 0; --n) {
      for (const int index : group_indices_[static_cast<std::size_t>(in.next_int())]) {
        router_.display(index).swap();
        shown_frame_[static_cast<std::size_t>(index)] =
            done_frame_[static_cast<std::size_t>(index)];
      }
    }
    std::vector<std::uint64_t> sequences(static_cast<std::size_t>(in.next_int()));
    for (auto& s : sequences) s = static_cast<std::uint64_t>(in.next());
    for (ColumnInput& input : inputs_) {
      input.receiver->take(sequences[static_cast<std::size_t>(input.server)], [] {});
      const auto f = input.receiver->latest();
      InputFrame& frame = frames_[static_cast<std::size_t>(input.server)];
      frame = {};
      if (!f) continue;
      frame = {f->pixels, static_cast<std::ptrdiff_t>(f->stride), f->width, f->height, 3};
      const ServerPlan& plan = layout_.servers[static_cast<std::size_t>(input.server)];
      input.stamp =
          plan.tiles.empty()
              ? -1
              : decode_stamp(frame.row(plan.tiles.front().fb_y) + plan.tiles.front().fb_x * 3);
    }
    router_.scan(frames_);
    mpi_wire::send(observation(refresh), RankMap::kCoordinator, mpi_wire::kObservation);
  }

  // [refresh, n, (server, present, idle, torn, parity, displays fed, stamp)...,
  //  n, (server, stamp on its display)..., n, (display, frame shown)...]
  Record observation(std::int64_t refresh) const {
    Record r{refresh, static_cast<std::int64_t>(inputs_.size())};
    for (const ColumnInput& input : inputs_) {
      const InputFrameStats& st = router_.scanned(input.server);
      r.insert(r.end(), {input.server, st.present, st.idle(), st.torn(), st.parity(),
                         static_cast<std::int64_t>(st.displays_fed), input.stamp});
    }
    Record shown;
    for (const ServerPlan& plan : layout_.servers) {
      if (plan.tiles.empty()) continue;
      const DisplayTile& t = plan.tiles.front().tile;
      const int index = router_.index_of_display(t.display);
      if (index < 0) continue;
      const RgbImage& front = router_.display(index).front();
      shown.insert(shown.end(), {plan.server, decode_stamp(front.row(t.on_display.y).data() +
                                                           t.on_display.x * 3)});
    }
    r.push_back(static_cast<std::int64_t>(shown.size() / 2));
    r.insert(r.end(), shown.begin(), shown.end());
    r.push_back(router_.display_count());
    for (int d = 0; d < router_.display_count(); ++d)
      r.insert(r.end(), {router_.display(d).id(), shown_frame_[static_cast<std::size_t>(d)]});
    return r;
  }

  // [kRoute, n, route per mesh input..., n, completed group indices...]
  void route(Reader& in) {
    std::vector<std::uint8_t> chosen(static_cast<std::size_t>(in.next_int()));
    for (auto& c : chosen) c = static_cast<std::uint8_t>(in.next());
    router_.write(chosen);
    // The frame a display's next picture holds: the newest stamp routed into it.
    for (const ColumnInput& input : inputs_) {
      if (!chosen[static_cast<std::size_t>(input.server)]) continue;
      const std::uint64_t fed = router_.scanned(input.server).displays_fed;
      for (int d = 0; d < router_.display_count(); ++d) {
        if (fed >> router_.display(d).id() & 1) {
          int& f = back_frame_[static_cast<std::size_t>(d)];
          f = std::max(f, input.stamp);
        }
      }
    }
    for (int n = in.next_int(); n > 0; --n) {
      const std::vector<int>& own = group_indices_[static_cast<std::size_t>(in.next_int())];
      router_.finish(own, finished_);
      for (const int index : own) {
        done_frame_[static_cast<std::size_t>(index)] = back_frame_[static_cast<std::size_t>(index)];
        back_frame_[static_cast<std::size_t>(index)] = -1;
      }
    }
  }

  void send_pictures() {
    for (int d = 0; d < router_.display_count(); ++d) {
      const RgbImage& front = router_.display(d).front();
      MPI_Send(front.data(), static_cast<int>(front.bytes().size()), MPI_BYTE,
               RankMap::kCoordinator, mpi_wire::kPicture, MPI_COMM_WORLD);
    }
  }

  const TileLayout& layout_;
  const RankMap& map_;
  int column_;
  WorkerPool pool_;
  Router router_;
  std::vector<ColumnInput> inputs_;
  std::vector<InputFrame> frames_;               // by mesh input; absent: no signal here
  std::vector<std::vector<int>> group_indices_;  // by group index: this column's display indices
  std::vector<int> back_frame_, done_frame_, shown_frame_;  // by display index
  std::vector<DisplayFrameStats> finished_;
};

}  // namespace

int run_column(const TileLayout& layout, const RankMap& map, int column, int threads) {
  Column c(layout, map, column, threads);
  c.run();
  return 0;
}

}  // namespace l2
