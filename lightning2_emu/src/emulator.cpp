#include "lightning2_emu/emulator.hpp"

#include <fmt/format.h>

namespace l2 {

Emulator::Emulator(const EmulatorConfig& config)
    : pool_(config.workers),
      router_(config.mesh, config.displays, pool_, config.background),
      sequencer_(config.mesh.input_count(),
                 static_cast<int>(make_swap_groups(config.displays).size())) {
  router_.predict_layouts(config.predict_layouts);
  report_.groups = make_swap_groups(config.displays);
  group_display_indices_.resize(report_.groups.size());
  group_of_display_.assign(router_.display_count(), 0);
  for (std::size_t g = 0; g < report_.groups.size(); ++g) {
    for (const int id : report_.groups[g].displays) {
      const int index = router_.index_of_display(id);
      group_of_display_[index] = static_cast<int>(g);
      group_display_indices_[g].push_back(index);
    }
  }
  report_.inputs.resize(config.mesh.input_count());
  for (int i = 0; i < config.mesh.input_count(); ++i) report_.inputs[i].input = i;
  report_.displays.resize(router_.display_count());
  for (int d = 0; d < router_.display_count(); ++d) {
    report_.displays[d].display = router_.display(d).id();
  }
}

const RgbImage& Emulator::shown(int display_id) const {
  const int index = router_.index_of_display(display_id);
  if (index < 0) throw MeshError(fmt::format("display {} is not configured", display_id));
  return router_.display(index).front();
}

void Emulator::decide(int inputs) {
  observations_.resize(inputs);
  tick_.inputs.clear();
  for (int i = 0; i < inputs; ++i) {
    const InputFrameStats& st = router_.scanned(i);
    tick_.inputs.push_back(st);
    FrameObservation& o = observations_[i];
    o = {st.present, st.idle(), st.torn(), st.parity(), 0};
    for (int d = 0; d < kMaxDisplays; ++d) {
      if (st.displays_fed >> d & 1) {
        o.groups_fed |= std::uint64_t{1} << group_of_display_[router_.index_of_display(d)];
      }
    }
  }
  sequencer_.decide(observations_, decision_);
}

const Emulator::Tick& Emulator::tick(std::span<const InputFrame> frames) {
  tick_.index = report_.ticks++;
  // 1. Output refresh.
  sequencer_.refresh(swapped_);
  tick_.swapped_groups.clear();
  for (const int g : swapped_) {
    for (const int d : group_display_indices_[g]) router_.display(d).swap();
    ++report_.groups[g].swaps;
    tick_.swapped_groups.push_back(report_.groups[g].id);
  }

  // 2. Parse, classify, route the new frames.
  router_.scan(frames);
  const int inputs = router_.mesh().input_count();
  router_.write([&] {
    decide(inputs);
    return std::span<const std::uint8_t>(decision_.route);
  });
  sequencer_.commit(observations_, decision_);
  tick_.kinds = decision_.kinds;
  tick_.ready_inputs = decision_.ready_inputs;
  report_.frames_predicted = router_.predictions().predicted;
  report_.predictions_missed = router_.predictions().mispredicted;
  for (int i = 0; i < inputs; ++i) {
    const InputFrameStats& st = tick_.inputs[i];
    InputRunStats& run = report_.inputs[i];
    run.copy_strips += st.copy_strips;
    run.key_strips += st.key_strips;
    run.depth_strips += st.depth_strips;
    run.skip_strips += st.skip_strips;
    run.errors += st.errors;
    ++run.frames[static_cast<int>(decision_.kinds[i])];
    if (decision_.route[i]) run.routed_strips += st.routed_strips;
  }

  // 3. Complete the groups that have everything (their hosts got READY above).
  tick_.completed_groups.clear();
  tick_.completed.clear();
  for (const int g : decision_.completed_groups) {
    tick_.completed_groups.push_back(report_.groups[g].id);
    router_.finish(group_display_indices_[g], finished_);
    for (std::size_t k = 0; k < finished_.size(); ++k) {
      DisplayRunStats& run = report_.displays[group_display_indices_[g][k]];
      ++run.frames;
      run.strips += finished_[k].strips;
      run.covered_pixels += finished_[k].covered_pixels;
      run.overdraw_pixels += finished_[k].overdraw_pixels;
      tick_.completed.push_back(finished_[k]);
    }
  }
  return tick_;
}

}  // namespace l2
