// One board column of a live run's Lightning-2 (spec §4): the router over its displays, their
// swap-lock groups, and the frame each display holds, from the stamps of the input frames routed
// into it. A stamp is read from its input's pixels, in the stamp strip no display shows
// (tile_layout.hpp); which input frame each display holds is this column's bookkeeping of what
// it routed, kept in step with the display buffers (back, completed, shown), so the displays
// carry no mark. At
// every refresh it does what the DVI path's tick and route say, in the spec's order: swap,
// scan, say what it saw, write the inputs chosen, complete the groups decided.
//
// In a wall of several meshes (tilelayout/several_meshes.hpp) a column is one mesh's: its router
// reads the ids the mesh's headers carry, and it answers in the wall's numbers (display ids,
// pipeservers), so the path above it is the same for one mesh or several.
//
// Owns: the router and its display buffers, the frame stamp of each of its inputs' frames, and
// the frame each of its displays holds in its back buffer, has completed, and shows. It does not
// decide anything (the frame sequencer is the DVI path's) and does no I/O: where its input frames
// come from is its owner's business (shared memory in one process, MPI on a column rank), so the
// same code runs the one-machine path and every column rank.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "l2wall/column_records.hpp"
#include "lightning2_emu/router.hpp"
#include "lightning2_emu/worker_pool.hpp"
#include "tilelayout/tile_layout.hpp"
#include "tilelayout/wall.hpp"

namespace l2 {

class BoardColumn {
 public:
  // The displays of `wall` with ids in `display_ids`, fed by the mesh inputs (pipeservers)
  // `pipeservers`, routed by `pool`'s workers. `predict`: Router::predict_layouts (a column
  // whose choice is a round trip away cannot be asked twice, so it parses every frame). In a
  // wall of several meshes the displays must be of one mesh, and the pipeservers its own.
  BoardColumn(const Wall& wall, std::span<const int> display_ids, std::vector<int> pipeservers,
              WorkerPool& pool, bool predict);

  // 1. The groups `groups` (indices into the wall's swap-lock groups) swap; true when one of
  // this column's displays did. Throws std::runtime_error for a group the wall lacks.
  bool swap(std::span<const int> groups);
  // 2. Scans `frames` (by mesh input; one not present: no signal). A frame whose sequence in
  // `tick` is new has its stamp read where `tick` says the next frame's is; an input with none
  // keeps the stamp it had.
  void scan(std::span<const InputFrame> frames, const Tick& tick);
  // What it saw, for refresh `refresh`.
  Observation observe(std::int64_t refresh) const;
  // 3. Writes the inputs chosen (ColumnRoute::route; `choose` may be asked twice, see
  // Router::write), then completes `groups` (indices).
  void write(const Router::RouteChoice& choose);
  void complete(std::span<const int> groups);

  Router& router() { return router_; }
  const Router& router() const { return router_; }
  // What the router calls input `pipeserver` (a wall pipeserver of this column's mesh).
  int router_input(int pipeserver) const { return pipeserver - mesh_.part.first_pipeserver; }
  int mesh() const { return mesh_.part.mesh; }
  // The front buffer of display `id`, one of this column's.
  const RgbImage& shown(int id) const;
  // The lowest frame its displays show; -1 before the first.
  int lowest_frame_shown() const;

 private:
  // The mesh the column's displays are on: the wall it sees (wall.hpp's displays renumbered as
  // its headers number them) and the numbers both ways.
  struct MeshView {
    MeshPart part;
    Wall wall;                    // mesh_wall: ids as the mesh's headers carry them
    std::vector<int> ids;         // the column's displays, as `wall` numbers them
    std::vector<int> mesh_id_of;  // by wall display id: the mesh's id, -1 for another mesh's
    MeshView(const Wall& w, std::span<const int> display_ids);
    int wall_id(int mesh_id) const { return part.displays[static_cast<std::size_t>(mesh_id)]; }
    int mesh_id(int wall_id) const;  // -1: not this mesh's display
  };

  MeshView mesh_;
  Router router_;
  std::vector<int> pipeservers_;                 // its inputs
  std::vector<std::vector<int>> group_indices_;  // by group index: this column's display indices
  std::vector<PipeserverStamps> spots_;          // by pipeserver: this refresh's (the tick's)
  std::vector<int> stamps_;                      // by mesh input: the stamp of the frame taken in
  std::vector<std::uint64_t> sequences_;         // by mesh input: the frame taken in
  std::vector<int> back_frame_, done_frame_, shown_frame_;  // by display index
  // By display index, by mesh input: the stamp of that input's frame routed into the display's
  // back buffer, its completed picture and the picture it shows (kStampNotHere: none).
  std::vector<std::vector<int>> back_from_, done_from_, shown_from_;
  std::vector<DisplayFrameStats> finished_;
};

}  // namespace l2
