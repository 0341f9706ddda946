// What the options of `l2wall run` mean together: the combinations that make no run (usage
// errors), the balancing they ask for and its refusals, and what every pipeserver is started
// with. No I/O: the command line checks these while parsing, the run again before it starts.
#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

#include "balance/balancer.hpp"
#include "l2wall/run_backends.hpp"
#include "l2wall/run_options.hpp"
#include "pipeserver/picture_cache.hpp"
#include "tilelayout/survival.hpp"

namespace l2 {

PipeserverLaunch pipeserver_launch(const RunOptions& o) {
  PipeserverLaunch l;
  l.program = o.pipeserver_program;
  l.wall = o.wall;
  l.scene = o.scene;
  l.scene_args = o.scene_args;
  l.out = o.out;
  l.frames = o.frames;
  l.ready_timeout_ms = o.ready_timeout_ms;
  l.dvi = false;  // unless a path links the pipeservers
  l.link_codec = o.link_codec;
  l.renderer = o.renderer;
  return l;
}

void add_picture_cache_default(PipeserverLaunch& l, int pipeservers, double physical_mb) {
  if (l.scene != "picture" && l.scene != "session") return;
  const auto& a = l.scene_args;
  if (std::find(a.begin(), a.end(), "--picture-cache-mb") != a.end()) return;
  l.scene_args.push_back("--picture-cache-mb");
  l.scene_args.push_back(fmt::format("{:.0f}", default_picture_cache_mb(physical_mb, pipeservers)));
}

Status run_options_error(const RunOptions& o) {
  if (o.compare && o.path != PathChoice::Both) return Failure{"--compare needs --path both"};
  if (o.window_stdin && o.scene != "session")
    return Failure{"--window-stdin moves a session's windows: it needs --scene session"};
  if (!o.tuio.empty() && o.scene != "session")
    return Failure{"--tuio moves a session's windows: it needs --scene session"};
  if (!o.vnc_password_file.empty() && o.scene != "vnc")
    return Failure{"--vnc-password-file is the password of --scene vnc's server"};
  if (runs_viz(o.path) && o.vizserver_program.empty())
    return Failure{"--vizserver-program: no compositing server executable given"};
  if (o.viz_port < 0 || o.viz_port > 65535)
    return Failure{fmt::format("--viz-port: {} is not 0..65535", o.viz_port)};
  // There is no compositing server on the DVI path: an address for it would go unused.
  if (!runs_viz(o.path) && (o.viz_port != 0 || o.viz_host != RunOptions{}.viz_host))
    return Failure{"--viz-host and --viz-port need --path vizserver or both"};
  SavedFrames saved;
  try {
    saved = parse_saved_frames(o.keep);
  } catch (const std::invalid_argument& e) {
    return Failure{e.what()};
  }
  // A frame the run never renders would silently keep nothing, or inject no fault, and the
  // run would pass as if the fault had been survived.
  const auto past_the_last = [&o](const char* option, int frame) -> Status {
    if (frame < o.frames) return {};
    return Failure{fmt::format("{}: frame {} is past the last frame (--frames {} renders 0..{})",
                               option, frame, o.frames, o.frames - 1)};
  };
  if (!saved.frames.empty()) {
    if (Status s = past_the_last("--keep", *saved.frames.rbegin()); !s.ok()) return s;
  }
  for (const auto& [option, frame] : {std::pair{"--inject-noise", o.noise_after},
                                      std::pair{"--inject-mismatch", o.inject_mismatch},
                                      std::pair{"--drop-ready", o.drop_ready}}) {
    if (Status s = past_the_last(option, frame); !s.ok()) return s;
  }
  if (o.inject_mismatch >= 0 && !o.compare) return Failure{"--inject-mismatch needs --compare"};
  return {};
}

std::vector<std::string> pausable_pipeserver_args(const RunOptions& o) {
  if (o.show.empty() && o.http.empty()) return {};
  return {"--ready-retries", "1000"};  // the pipeserver's largest: 1000 SYNC? before giving up
}

BalanceSpec run_balance(const RunOptions& o, const Wall& wall) {
  BalanceSpec spec = wall.balance;
  if (const auto mode = parse_balance_mode(o.balance)) spec.mode = *mode;
  spec.survive_host_loss = spec.survive_host_loss || o.survive_host_loss;
  spec.resistance = o.resistance.value_or(spec.resistance);
  spec.tile_cost = o.tile_cost.value_or(spec.tile_cost);
  return spec;
}

namespace {

// The option or the wall file's line that asked for survival, as messages name it.
std::string survive_asked_by(const RunOptions& o, const Wall& wall) {
  if (o.survive_host_loss) return "--survive-host-loss";
  return fmt::format("{}:{}: balance.survive_host_loss", wall.source.string(), wall.balance.line);
}

}  // namespace

std::string survival_note(const RunOptions& o, const Wall& wall) {
  if (!run_balance(o, wall).survive_host_loss) return {};
  const Survival s = survival(wall);
  // Asked for and not offered: the user would otherwise learn it only from a loss.
  const std::string ends = s.survives == 0 ? "; a pipeserver that dies ends the run" : "";
  return fmt::format("{}: the wall {}{}", survive_asked_by(o, wall), survival_line(wall, s), ends);
}

Status balance_refusal(const RunOptions& o, const Wall& wall, RunPlace place) {
  const BalanceSpec spec = run_balance(o, wall);
  if (!spec.balancing()) {
    // Only a balancing run re-plans, so only it can hand a dead pipeserver's tiles to the others.
    if (o.survive_host_loss) {
      return Failure{
          "--survive-host-loss needs balancing: --balance strips or kd, or a wall file's "
          "[balance]"};
    }
    if (o.resistance || o.tile_cost) {
      return Failure{
          fmt::format("{} needs balancing: --balance strips or kd, or a wall file's [balance]",
                      o.resistance ? "--resistance" : "--tile-cost")};
    }
    if (spec.survive_host_loss) {  // the wall's, balancing turned off by --balance static
      return Failure{fmt::format(
          "{}:{}: balance.survive_host_loss needs balancing, which --balance static turns off",
          wall.source.string(), spec.line)};
    }
    return {};
  }
  // A wall of several meshes is planned mesh by mesh, each with its own pipeservers: a
  // re-tiling would have to move tiles within each mesh alone.
  if (wall.mesh_count > 1) {
    return Failure{fmt::format(
        "--balance: balancing is for a wall of one mesh; this wall's {} displays need {} meshes",
        wall.displays.size(), wall.mesh_count)};
  }
  // A stereo wall's eyes are twins tile for tile; a re-tiling would have to keep them alike.
  // The wall file's [balance] is refused on one (wall_stereo.cpp); the option is too.
  if (wall.stereo.on()) return Failure{"--balance: stereo walls do not support balancing yet"};
  const std::string survive = survive_asked_by(o, wall);
  // By default a rank that dies ends the whole mpirun job: there would be no run left to go on.
  if (spec.survive_host_loss && place == RunPlace::MpiEndingOnLoss)
    return Failure{fmt::format(
        "{}: over MPI (--mpi) needs an mpirun that keeps the job when a rank dies: mpirun {} "
        "...",
        survive, kMpirunKeepsJob)};
  // A frame shown stale keeps older pixels where the lost pipeserver's tiles were on the DVI
  // path, and the background on the vizserver path: the two paths would differ there.
  if (spec.survive_host_loss && o.path == PathChoice::Both) {
    return Failure{survive +
                   ": runs on --path dvi or vizserver, not both (a frame shown stale differs "
                   "between them: older pixels on the DVI path, the background on the "
                   "vizserver path)"};
  }
  return {};
}

Status stereo_refusal(const RunOptions& o, const Wall& wall) {
  // A packed display's halves show the scene's picture squeezed: pixels and windows are drawn
  // at canvas pixels, one to one, and cannot be.
  const bool pixels =
      o.scene == "picture" || o.scene == "movie" || o.scene == "session" || o.scene == "vnc";
  if (packed_stereo(wall.stereo) && pixels) {
    return Failure{fmt::format(
        "--scene {}: packed stereo walls (side-by-side, top-bottom) do not support it (its "
        "pixels are drawn one to one, not squeezed into each eye's half)",
        o.scene)};
  }
  if (wall.stereo.mode != StereoMode::Active) return {};
  // What changes between eye frames from outside (windows moved, a desktop's pixels) could land
  // between a frame's two eyes: each eye would show a different frame.
  if (o.scene == "session" || o.scene == "vnc") {
    return Failure{fmt::format(
        "--scene {}: active stereo walls do not support it yet (its windows or desktop could "
        "change between a frame's left and right eye)",
        o.scene)};
  }
  // Its clock runs at the refresh rate, which shows an active wall's frames at half of it.
  if (o.scene == "movie")
    return Failure{
        "--scene movie: active stereo walls do not support it yet (it would play at "
        "half speed)"};
  if (o.frames % 2 != 0) {
    return Failure{fmt::format(
        "--frames {}: an active stereo wall's frames are eye frames (left and right of each "
        "application frame): give an even count",
        o.frames)};
  }
  return {};
}

}  // namespace l2
