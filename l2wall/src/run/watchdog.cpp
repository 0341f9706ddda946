#include "watchdog.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstdio>

#include "l2wall/run_fault.hpp"
#include "l2wall/stop_signal.hpp"
#include "pipeserver/live_exit.hpp"
#include "stall_verdict.hpp"

namespace l2 {
namespace {

// A pipeserver that gave up waiting for READY or SWAPPED: the effect of another's fault.
bool ended_giving_up(const LivePipeserver& h) {
  return h.exit && h.exit->signal == 0 && gave_up_waiting(h.exit->code);
}

}  // namespace

void Watchdog::check_processes() {
  const FrameLedger& f = core_.frames;
  if (f.stopped) return;  // the processes are ending by the signal; the run is over
  check_stop_signal(f.shown, displays_showing());
  LivePipeserver* ended = core_.pipeservers.poll_ended();
  while (ended && survive(*ended)) ended = core_.pipeservers.poll_ended();
  const bool path_down =
      std::any_of(core_.paths.begin(), core_.paths.end(), [](const auto& p) { return p->down(); });
  if (ended || path_down) throw RunFault(blame());
}

// --survive-host-loss: the run goes on without a pipeserver that ended, its tiles planned over
// the others from the next layout on. False when it cannot (no balancing run, not yet running,
// the last pipeserver) or should not (the pipeserver gave up waiting for READY: an effect whose
// cause blame() names): the run ends on it as without the option.
bool Watchdog::survive(LivePipeserver& h) {
  const FrameLedger& f = core_.frames;
  LiveBalance* balance = core_.balance.get();
  if (!balance || !balance->survives_losses() || !f.pipeservers_started) return false;
  if (ended_giving_up(h)) return false;
  const std::string how = core_.pipeservers.ended_how(h);
  // Lost while the run starts (before every first frame), it is lost at the run's second 0.
  const double seconds = f.links_open ? ms_between(f.totals.start, RunClock::now()) / 1000.0 : 0.0;
  if (!balance->lose(h.pipeserver, core_.pipeservers.delivered(h), how, seconds)) return false;
  core_.pipeservers.lose(h);
  for (auto& p : core_.paths) p->lose_pipeserver(h.pipeserver);
  std::fprintf(stderr, "%sl2wall: %s; the run goes on without it (--survive-host-loss)\n",
               progress_.shown() ? "\n" : "", how.c_str());
  if (core_.page) core_.page->event(f.shown - 1, how + "; the run goes on without it");
  return true;
}

// When one process fails the others lose their connection to it and end too; name the cause. A
// process killed by a signal is never such an effect. A compositing server that died without
// saying why is the cause of the pipeservers losing it; one that said why (a pipeserver
// disconnected) is an effect, its words name the pipeserver. One still running that a
// pipeserver gave up on hangs: it is named, not the pipeserver.
std::string Watchdog::blame() {
  const int shown = core_.frames.shown;
  for (auto& p : core_.paths) p->settle(std::chrono::milliseconds(300));
  if (LivePipeserver* killed = core_.pipeservers.killed_by_signal())
    return core_.pipeservers.describe_end(*killed, displays_showing());
  for (auto& p : core_.paths) {
    if (const Status why = p->failure_as_cause(shown, displays_showing()); !why.ok())
      return why.reason();
  }
  if (LivePipeserver* ended = core_.pipeservers.poll_ended()) return blame_given_up(*ended);
  for (auto& p : core_.paths) {
    if (const Status why = p->failure(shown, displays_showing()); !why.ok()) return why.reason();
  }
  return "a process of the run ended";
}

// A pipeserver that gave up waiting (for READY or SWAPPED) is an effect when another, still
// there, never delivered the frame everyone waits for: that one stopped answering. Else a path
// that hangs behind it, else its own end.
std::string Watchdog::blame_given_up(const LivePipeserver& ended) {
  const int shown = core_.frames.shown;
  if (ended_giving_up(ended)) {
    if (const LivePipeserver* hung = core_.pipeservers.hung_pipeserver(shown)) {
      return fmt::format(
          "pipeserver {} ({}) stopped answering{}: it did not deliver frame {}, and "
          "pipeserver {} gave up {} ({}); {}",
          hung->pipeserver, hung->process->place(), PipeserverSet::stopped_note(*hung), shown,
          ended.pipeserver, waiting_for(ended), ended.exit->describe(), displays_showing());
    }
  }
  for (auto& p : core_.paths) {
    if (const Status why = p->hang_behind(ended, shown, displays_showing()); !why.ok())
      return why.reason();
  }
  return core_.pipeservers.describe_end(ended, displays_showing());
}

// What a pipeserver that gave up was waiting for, by its exit code.
std::string Watchdog::waiting_for(const LivePipeserver& h) const {
  if (h.exit->code == kExitNoReady) return "waiting for READY";
  const std::string server = server_process();
  return "waiting for SWAPPED from the " + (server.empty() ? std::string("vizserver") : server);
}

// How messages name the process a path runs (the compositing server), or empty.
std::string Watchdog::server_process() const {
  for (const auto& p : core_.paths) {
    if (std::string name = p->process_name(); !name.empty()) return name;
  }
  return {};
}

void Watchdog::check_stall() {
  const FrameLedger& f = core_.frames;
  const RunOptions& o = core_.options;
  if (f.shown >= o.frames) return;  // every frame is on the displays: nothing to wait for
  // Before the first swap the pipeservers may still be starting (GL context, first render).
  const int limit_ms = f.shown == 0 ? o.start_timeout_ms : o.stall_timeout_ms;
  const double waited_ms = ms_between(f.last_swap, RunClock::now());
  if (waited_ms < limit_ms) return;
  // A pipeserver that has not delivered the frame the displays wait for is the one that hangs;
  // if every pipeserver delivered it, the compositing server did not.
  std::string culprits = core_.pipeservers.late_pipeservers(f.shown);
  if (const std::string server = server_process(); culprits.empty() && !server.empty())
    culprits = "the " + server;
  if (!stall_ends_run(waited_ms, limit_ms, !culprits.empty())) return;
  if (culprits.empty()) {
    throw RunFault(fmt::format(
        "no display swap for {:.0f} ms though every pipeserver delivered frame {}: no process "
        "of the run is late (was the machine too busy?); {}",
        waited_ms, f.shown, displays_showing()));
  }
  throw RunFault(fmt::format("no display swap for {} ms: {} did not deliver frame {}{}; {}",
                             limit_ms, culprits, f.shown, stall_note(), displays_showing()));
}

// What the pipeservers that did deliver are doing: waiting for the swap that cannot come.
std::string Watchdog::stall_note() const {
  const int shown = core_.frames.shown;
  const auto& all = core_.pipeservers.all();
  const bool some_delivered = std::any_of(all.begin(), all.end(), [&](const LivePipeserver& h) {
    return core_.pipeservers.delivered(h) > shown;
  });
  const LivePipeserver* hung = some_delivered ? core_.pipeservers.hung_pipeserver(shown) : nullptr;
  if (!hung) return {};
  return fmt::format("{}; the other pipeservers are waiting for {}",
                     PipeserverSet::stopped_note(*hung),
                     core_.paths.front()->pipeservers_wait_for());
}

std::string Watchdog::displays_showing() const {
  const auto& paths = core_.paths;
  if (paths.empty()) return "no frame reached the displays";
  const int frame = paths.front()->frame_shown();
  const bool same = std::all_of(paths.begin(), paths.end(),
                                [&](const auto& p) { return p->frame_shown() == frame; });
  if (same) {
    if (frame < 0) return "no frame reached the displays";  // not "frame -1"
    return fmt::format("the displays keep frame {}", frame);
  }
  std::string each;
  for (const auto& p : paths)
    each +=
        fmt::format("{}frame {} ({})", each.empty() ? "" : " and ", p->frame_shown(), p->name());
  return "the displays keep " + each;
}

}  // namespace l2
