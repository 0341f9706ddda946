#include "column_rank.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <vector>

#include "column_messages.hpp"
#include "column_show.hpp"
#include "l2wall/board_column.hpp"
#include "mpi_link/mpi_dvi_link.hpp"
#include "mpi_link/mpi_wire.hpp"
#include "viz_link/tile_delta.hpp"
#include "vizserver/frame_assembler.hpp"

namespace l2 {
namespace {

using mpi_wire::Reader;
using mpi_wire::Record;

struct ColumnInput {
  int pipeserver = 0;
  std::unique_ptr<MpiDviReceiver> receiver;
};

class Column {
 public:
  Column(const TileLayout& layout, const RankMap& map, int column, const RunOptions& o,
         ColumnShow* show)
      : layout_(layout),
        map_(map),
        column_index_(column),
        pool_(o.threads),
        // Every refresh's layout is parsed: the prediction's second choice (router.hpp) would be
        // a second round trip to the coordinator.
        column_(layout.wall, map.displays_of_column[static_cast<std::size_t>(column)],
                map.pipeservers_of_column[static_cast<std::size_t>(column)], pool_,
                /*predict=*/false),
        frames_(static_cast<std::size_t>(map.mesh_inputs)),
        show_(show) {
    for (const int s : map.pipeservers_of_column[static_cast<std::size_t>(column)]) {
      const PipeserverPlan& plan = layout.pipeservers[static_cast<std::size_t>(s)];
      inputs_.push_back({s, std::make_unique<MpiDviReceiver>(map.pipeserver_rank(s), plan.fb_width,
                                                             plan.fb_height)});
    }
    if (o.path == PathChoice::Both) {
      std::vector<std::pair<int, int>> sizes;
      for (const Display& d : layout.wall.displays) sizes.emplace_back(d.width, d.height);
      assembler_.emplace(std::move(sizes), map.pipeservers);
      for (int s = 0; s < map.pipeservers; ++s) {
        if (const Status joined = assembler_->connect(s); !joined.ok())
          throw std::runtime_error(joined.reason());
      }
    }
  }

  void run() {
    for (;;) {
      const Record command =
          mpi_wire::receive_watched(RankMap::kCoordinator, mpi_wire::kCommand, pump_);
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
        case mpi_wire::kFetchComposed:
          send_composed(static_cast<std::uint32_t>(in.next()));
          break;
        case mpi_wire::kEnd:
          return;
        default:
          throw std::runtime_error("unknown command from the coordinator");
      }
    }
  }

 private:
  // The groups swap, each input's frame of the tick is taken in (waiting for it), and what the
  // column saw goes to the coordinator.
  void tick(Reader& in) {
    const Tick tick = decode_tick(in);
    if (column_.swap(tick.swapped_groups) && show_) present();
    for (ColumnInput& input : inputs_) {
      const auto p = static_cast<std::size_t>(input.pipeserver);
      if (p >= tick.sequences.size())
        throw std::runtime_error(fmt::format("the coordinator's tick has no pipeserver {}", p));
      InputFrame& frame = frames_[p];
      frame = {};
      if (tick.sequences[p] == kNoSignal) input.receiver->lose();  // its pipeserver is lost
      if (input.receiver->lost()) continue;
      input.receiver->take(tick.sequences[p], pump_);
      if (const auto f = input.receiver->latest())
        frame = {f->pixels, static_cast<std::ptrdiff_t>(f->stride), f->width, f->height, 3};
    }
    column_.scan(frames_, tick);
    mpi_wire::send(encode(column_.observe(tick.refresh)), RankMap::kCoordinator,
                   mpi_wire::kObservation);
  }

  void present() {
    show_->present(column_.lowest_frame_shown(),
                   [this](int id) -> const RgbImage& { return column_.shown(id); });
  }

  // The route the coordinator chose: the inputs written, the groups completed.
  void route(Reader& in) {
    const ColumnRoute route = decode_route(in);
    column_.write([&] { return std::span<const std::uint8_t>(route.route); });
    column_.complete(route.completed_groups);
  }

  // What the coordinator says at any time: a pipeserver lost (its frame being waited for may
  // never arrive whole); the viz path's tiles.
  void pump() {
    take_losses();
    pump_tiles();
  }

  void take_losses() {
    while (mpi_wire::waiting(RankMap::kCoordinator, mpi_wire::kLost)) {
      Reader in(mpi_wire::receive(RankMap::kCoordinator, mpi_wire::kLost));
      const int pipeserver = in.next_int();
      for (ColumnInput& input : inputs_)
        if (input.pipeserver == pipeserver) input.receiver->lose();
    }
  }

  // Takes in every tile and frame end waiting; sends the coordinator each frame composed.
  void pump_tiles() {
    if (!assembler_) return;
    for (;;) {
      int flag = 0;
      MPI_Status status;
      MPI_Iprobe(MPI_ANY_SOURCE, mpi_wire::kTile, MPI_COMM_WORLD, &flag, &status);
      if (!flag) break;
      int bytes = 0;
      MPI_Get_count(&status, MPI_BYTE, &bytes);
      tile_bytes_.resize(static_cast<std::size_t>(bytes));
      mpi_wire::receive_bytes(tile_bytes_, status.MPI_SOURCE, mpi_wire::kTile);
      mpi_wire::TileMessage m;
      if (tile_bytes_.size() < sizeof m) throw std::runtime_error("a tile message too short");
      std::memcpy(&m, tile_bytes_.data(), sizeof m);
      const auto pipeserver = map_.pipeserver_of(status.MPI_SOURCE);
      if (!pipeserver) throw std::runtime_error("a tile from a rank that is no pipeserver");
      Status taken;
      if (m.kind == mpi_wire::kTileDeltaKind) {
        const viz::TileHeader header{m.frame, m.display, m.dx, m.dy, m.w, m.h, viz::TileKind{m.how},
                                     m.key};
        const std::span<const std::uint8_t> encoded = std::span(tile_bytes_).subspan(sizeof m);
        if (const Status valid =
                viz::validate_delta(header, static_cast<std::uint32_t>(32 + encoded.size()));
            !valid.ok())
          throw std::runtime_error("a tile message: " + valid.reason());
        auto& deltas =
            tile_deltas_.try_emplace(*pipeserver, assembler_->tile_delta_budget()).first->second;
        Result<std::vector<std::uint8_t>> pixels = deltas.decode(header, encoded);
        if (!pixels.ok())
          throw std::runtime_error(fmt::format("pipeserver {}: {}", *pipeserver, pixels.reason()));
        taken = assembler_->add_tile(*pipeserver, {header, std::move(pixels).value()});
      } else if (m.kind == mpi_wire::kTileKind) {
        viz::ReceivedTile tile{
            {m.frame, m.display, m.dx, m.dy, m.w, m.h, viz::TileKind{m.how}, m.key},
            std::vector<std::uint8_t>(tile_bytes_.begin() + sizeof m, tile_bytes_.end())};
        if (const Status valid = viz::validate(
                tile.header,
                static_cast<std::uint32_t>(tile.header.fixed_size() + tile.pixels.size()));
            !valid.ok())
          throw std::runtime_error("a tile message: " + valid.reason());
        taken = assembler_->add_tile(*pipeserver, std::move(tile));
      } else {
        taken = assembler_->finish(*pipeserver,
                                   {static_cast<std::uint32_t>(*pipeserver), m.frame, m.tiles});
        if (const auto d = tile_deltas_.find(*pipeserver); taken.ok() && d != tile_deltas_.end())
          d->second.end_frame();
      }
      if (!taken.ok()) throw std::runtime_error(taken.reason());
    }
    for (viz::ComposedFrame& f : assembler_->take_complete()) {
      mpi_wire::send({static_cast<std::int64_t>(f.frame)}, RankMap::kCoordinator,
                     mpi_wire::kComposed);
      // Only this column's displays are kept (the assembler composes every display's image).
      for (std::size_t i = 0; i < f.displays.size(); ++i) {
        if (!own(layout_.wall.displays[i].id)) f.displays[i] = RgbImage();
      }
      composed_[f.frame] = std::move(f.displays);
      while (composed_.size() > 4) composed_.erase(composed_.begin());  // the run takes each
    }
  }

  // Whether display `id` (the wall's number) is one of this column's.
  bool own(int id) const {
    return map_.column_of_display.at(static_cast<std::size_t>(id)) == column_index_;
  }

  void send_composed(std::uint32_t frame) {
    const auto it = composed_.find(frame);
    if (it == composed_.end()) throw std::runtime_error("asked for a frame not composed here");
    for (std::size_t i = 0; i < layout_.wall.displays.size(); ++i) {
      const int id = layout_.wall.displays[i].id;
      if (!own(id)) continue;  // another column's
      const RgbImage& picture = it->second[i];
      mpi_wire::send_bytes(picture.bytes(), RankMap::kCoordinator, mpi_wire::kPicture);
    }
  }

  void send_pictures() {
    for (int d = 0; d < column_.router().display_count(); ++d) {
      const RgbImage& front = column_.router().display(d).front();
      mpi_wire::send_bytes(front.bytes(), RankMap::kCoordinator, mpi_wire::kPicture);
    }
  }

  const TileLayout& layout_;
  const RankMap& map_;
  int column_index_;
  WorkerPool pool_;
  BoardColumn column_;
  std::vector<ColumnInput> inputs_;
  std::vector<InputFrame> frames_;                // by mesh input; absent: no signal here
  std::optional<viz::FrameAssembler> assembler_;  // the viz path
  std::map<std::uint32_t, std::vector<RgbImage>> composed_;  // by frame: every display
  std::vector<std::uint8_t> tile_bytes_;
  std::map<int, viz::TileDeltaDecoder> tile_deltas_;  // by pipeserver: its TILE_DELTA tiles
  ColumnShow* show_;                                  // --show monitors, or null
  const std::function<void()> pump_ = [this] { pump(); };
};

}  // namespace

int run_column(const TileLayout& layout, const RankMap& map, int column, const RunOptions& o,
               ColumnShow* show) {
  Column c(layout, map, column, o, show);
  c.run();
  return 0;
}

}  // namespace l2
