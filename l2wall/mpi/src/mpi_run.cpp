#include "l2wall/mpi_run.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "column_rank.hpp"
#include "image/folders.hpp"
#include "l2wall/dvi_path.hpp"
#include "l2wall/pipeserver_set.hpp"
#include "l2wall/run_backends.hpp"
#include "l2wall/stop_signal.hpp"
#include "l2wall/viz_path.hpp"
#include "mpi_columns.hpp"
#include "mpi_compositors.hpp"
#include "mpi_link/busy_polling.hpp"
#include "mpi_link/mpi_control_channel.hpp"
#include "mpi_link/mpi_ready_channel.hpp"
#include "mpi_link/mpi_session.hpp"
#include "mpi_link/mpi_wire.hpp"
#include "mpi_link/rank_map.hpp"
#include "tilelayout/planner.hpp"
#include "tilelayout/wall_file.hpp"

namespace l2 {
namespace {

constexpr const char* kOnlyDvi =
    "--mpi: --path vizserver does not run over MPI alone; --path dvi or both";

// The scenes whose pipeservers take lines of the coordinator each frame (WANT out): a vnc run's
// desktop, a session's windows (and its desktops), as balanced layouts travel (kControl).
bool takes_windows(const std::string& scene) {
  return scene == "vnc" || scene == "session";
}

class MpiBackends final : public RunBackends {
 public:
  MpiBackends(const TileLayout& layout, const RankMap& map, MpiSession& session,
              const RunOptions& o)
      : layout_(layout), map_(map), session_(session), stall_timeout_ms_(o.stall_timeout_ms) {}

  std::unique_ptr<DisplayPath> dvi_path(const TileLayout& layout,
                                        const RunOptions& o) const override {
    return std::make_unique<DviPath>(layout, o,
                                     std::make_unique<MpiColumns>(layout, map_, session_, o));
  }
  bool stops_pipeservers_early() const override { return false; }
  bool fault_said(const std::string& line) const override { return session_.said(line); }
  std::unique_ptr<DisplayPath> viz_path(const TileLayout& layout, const VizLaunch&) const override {
    return std::make_unique<VizPath>(
        std::make_unique<MpiCompositors>(layout_, map_, stall_timeout_ms_),
        ColourStage(layout.wall));
  }
  void start_pipeservers(PipeserverSet& pipeservers, const PipeserverLaunch& launch,
                         const TileLayout& layout) const override {
    pipeservers.attach(launch, layout, [this, &launch](int pipeserver) {
      const int rank = map_.pipeserver_rank(pipeserver);
      const RankIdentity& who = session_.identities()[static_cast<std::size_t>(rank)];
      PipeserverSet::RemoteEnd end;
      end.process = remote_pipeserver_process(
          fmt::format("rank {} on {}, pid {}", rank, who.host, who.pid),
          [this, rank] { return session_.gone(rank); },
          [this, rank] { return session_.loss_cause(rank); },
          [this, rank] { return session_.exit_code(rank); });
      end.channel = std::make_unique<MpiReadyChannel>(rank, fmt::format("MPI rank {}", rank));
      // Balancing: the rank was started with --mpi-control (exec_pipeserver).
      if (launch.control)
        end.control = std::make_unique<MpiControlChannel>(rank, mpi_wire::kControl);
      // A vnc run's desktop, a session's windows: the rank was started with --mpi-windows
      // (exec_pipeserver).
      if (launch.windows && takes_windows(launch.scene))
        end.windows = std::make_unique<MpiControlChannel>(rank, mpi_wire::kWindows);
      return end;
    });
  }

 private:
  const TileLayout& layout_;
  const RankMap& map_;
  MpiSession& session_;
  int stall_timeout_ms_;
};

// Becomes pipeserver `pipeserver`; returns only when that failed. `balanced`: it sends its
// times and takes its layouts over MPI (the coordinator's MpiControlChannel).
int exec_pipeserver(const RunOptions& o, int pipeserver, bool balanced) {
  LivePipeserver h;
  h.pipeserver = pipeserver;
  h.report_path =
      (std::filesystem::path(o.out) / fmt::format("pipeserver-{}.log", pipeserver)).string();
  PipeserverLaunch launch = pipeserver_launch(o);
  launch.extra_args = {"--mpi", "--start-timeout", std::to_string(o.start_timeout_ms),
                       "--liveness-timeout", std::to_string(o.liveness_timeout_ms)};
  if (o.path == PathChoice::Both) launch.extra_args.push_back("--mpi-viz");
  if (balanced) launch.extra_args.push_back("--mpi-control");
  if (takes_windows(o.scene)) launch.extra_args.push_back("--mpi-windows");
  // Only the control page pauses an MPI run: the columns' windows take no keys.
  RunOptions pausable = o;
  pausable.show.clear();
  for (const std::string& a : pausable_pipeserver_args(pausable)) launch.extra_args.push_back(a);
  // Its report goes to --out on the machine it runs on, which the coordinator may not share.
  make_folders(o.out, "--out");
  const std::vector<std::string> args = pipeserver_argv(launch, h);
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  execv(argv[0], argv.data());
  std::fprintf(stderr, "l2wall: pipeserver %d: cannot run %s: %s\n", pipeserver, argv[0],
               std::strerror(errno));
  return 1;
}

int run_column_rank(const TileLayout& layout, const RankMap& map, int column, const RunOptions& o,
                    int rank, ColumnShow* show) {
  try {
    return run_column(layout, map, column, o, show);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "l2wall: %s (rank %d): %s\n", map.role(rank).c_str(), rank, e.what());
    MpiSession::abort_all(1);
  }
}

}  // namespace

Status mpi_options_error(const RunOptions& o) {
  if (!runs_dvi(o.path)) return Failure{kOnlyDvi};
  if (o.show == "window")
    return Failure{
        "--mpi: --show window is one machine's; --show monitors shows each column's displays "
        "on its own machine's monitors"};
  if (o.noise_after >= 0) return Failure{"--mpi: --inject-noise needs a serial line (no --mpi)"};
  return {};
}

bool coordinator_rank() {
  const auto launched = launched_rank();
  return !launched || launched->rank == RankMap::kCoordinator;
}

int run_wall_mpi(const RunOptions& o) {
  const auto launched = launched_rank();
  if (!launched) {
    std::fprintf(stderr,
                 "l2wall: --mpi: not started by mpirun (no OMPI_COMM_WORLD_RANK); run "
                 "mpirun -np N l2wall run --wall WALL --mpi\n");
    return 1;
  }
  // Before MPI_Init every rank checks alike; only rank 0 says why, once, and fails: mpirun
  // would end the job at the first rank that failed, perhaps before rank 0 has said it.
  const auto refuse = [&](const std::string& why) {
    if (launched->rank != 0) return 0;
    std::fprintf(stderr, "l2wall: %s\n", why.c_str());
    return 1;
  };
  if (const Status s = mpi_options_error(o); !s.ok()) return refuse(s.reason());
  std::optional<TileLayout> layout;
  std::optional<RankMap> map;
  bool balanced = false;
  try {
    layout = plan_layout(o.wall.empty() ? default_wall() : load_wall(o.wall));
    balanced = run_balance(o, layout->wall).balancing();
    // Every rank builds the same map (the pipeservers too, from --mpi-control).
    map = make_rank_map(*layout, balanced);
  } catch (const std::exception& e) {
    return refuse(e.what());
  }
  const RunPlace place = launched->keeps_job ? RunPlace::MpiKeepingJob : RunPlace::MpiEndingOnLoss;
  if (const Status s = balance_refusal(o, layout->wall, place); !s.ok()) return refuse(s.reason());
  if (const Status s = stereo_refusal(o, layout->wall); !s.ok()) return refuse(s.reason());
  if (const Status s = rank_count_error(*map, launched->size); !s.ok()) return refuse(s.reason());
  if (const auto pipeserver = map->pipeserver_of(launched->rank))
    return exec_pipeserver(o, *pipeserver, balanced);
  const auto column = map->column_of(launched->rank);
  std::optional<ColumnShow> show;
  if (column && !o.show.empty()) {
    // Before MPI_Init: a column that cannot show fails alone, and mpirun ends the job.
    try {
      // Vsync paces a refresh-rate run like a real display; --refresh 0 asks for full speed.
      show.emplace(layout->wall, map->displays_of_column[static_cast<std::size_t>(*column)],
                   o.refresh_hz > 0, o.show_readback);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "l2wall: %s (rank %d): %s\n", map->role(launched->rank).c_str(),
                   launched->rank, e.what());
      return 1;
    }
  }

  MpiSession session(std::chrono::milliseconds(o.start_timeout_ms),
                     std::chrono::milliseconds(o.liveness_timeout_ms));
  if (column)
    return run_column_rank(*layout, *map, *column, o, session.rank(), show ? &*show : nullptr);
  // A machine with more ranks than cores whose MPI busy-polls: said once, before the frames.
  if (const auto line = busy_polling_warning(session.identities()))
    std::fprintf(stderr, "l2wall: --mpi: %s\n", line->c_str());
  // The coordinator shows nothing: the columns show their displays (column_show.hpp).
  RunOptions coordinator = o;
  coordinator.show.clear();
  coordinator.show_readback.clear();
  const MpiBackends backends(*layout, *map, session, coordinator);
  const int code = run_wall(coordinator, backends);
  // Ctrl-C on mpirun (SIGTERM to every rank): the report is written and the line printed; the
  // other ranks wait for this word (deferred_stop.hpp) before mpirun's SIGKILL.
  if (stop_signal_received()) session.end_stopped(code);
  if (code != 0) MpiSession::abort_all(code);  // ranks may still wait for us
  session.end_job_after_loss();
  return 0;
}

}  // namespace l2
