// The DVI link as MPI messages (the MPI backend of dvi_link.hpp's interfaces): a pipeserver's
// scanned-out frame goes to every board column its tiles land on, as the DVI repeaters give a
// column every input it needs, and to no other; the coordinator hears of each frame in a
// small notice, so it can tell every column which frame of an input a refresh takes in.
// A frame travels as what changed since the last one sent to that column (frame_delta.hpp),
// the strips of other columns' displays black, so it fits a real network; the column
// rebuilds it byte for byte.
#pragma once

#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include <mpi.h>

#include "dvi_link/dvi_link.hpp"
#include "dvi_link/frame_delta.hpp"

namespace l2 {

// Bytes of frames sent: as scanned out (every column's copy) and as they went on the wire, and
// of those on the wire the first frame's (it starts from black: what a still picture costs
// is what comes after it).
struct SentBytes {
  std::uint64_t raw = 0, wire = 0, first_wire = 0;
};

// A column a frame goes to, how, and what of it the column has no use for (sent black).
struct ColumnFeed {
  int rank = 0;
  LinkCodec codec = LinkCodec::Zstd;
  std::vector<BlankRect> blank;
};

class MpiDviSender final : public DviSender {
 public:
  MpiDviSender(std::vector<ColumnFeed> columns, int coordinator_rank, int width, int height,
               std::shared_ptr<SentBytes> bytes_sent);

  std::span<std::uint8_t> back_frame() override;
  // Sends the back frame to every column (returning once they have it, so the frame can be
  // drawn again), then the notice to the coordinator. Throws std::runtime_error when MPI fails.
  std::uint64_t publish() override;

 private:
  // Columns with the same codec and blank rects share an encoder and a message.
  struct Stream {
    LinkCodec codec;
    std::vector<BlankRect> blank;
    std::vector<int> ranks;
    FrameDeltaEncoder encoder;
    std::vector<std::uint8_t> message;  // sequence number, then the encoded frame
  };
  std::vector<Stream> streams_;
  int coordinator_;
  // A whole-frame stream without black strips is scanned out into where its message carries
  // the rows, and sent as it is: no copy, as over a DVI cable. Else the frame is its own.
  Stream* in_place_ = nullptr;
  std::vector<std::uint8_t> own_frame_;
  std::span<std::uint8_t> frame_;  // the back frame
  std::uint64_t sequence_ = 0;
  std::shared_ptr<SentBytes> bytes_sent_;
};

// One input of a board column. A receive is always posted, so a frame moves while the column
// routes; take() makes the frame of the sequence number the coordinator named the latest().
class MpiDviReceiver final : public DviReceiver {
 public:
  MpiDviReceiver(int source_rank, int width, int height);
  ~MpiDviReceiver() override;
  MpiDviReceiver(const MpiDviReceiver&) = delete;
  MpiDviReceiver& operator=(const MpiDviReceiver&) = delete;

  // Waits for frame `sequence` (0: none yet, nothing to wait for), calling `watch` meanwhile;
  // older frames are dropped. Returns without it once `watch` has lost the input (lose()).
  void take(std::uint64_t sequence, const std::function<void()>& watch);
  std::optional<FrameView> latest() override;
  // Its sender is gone (a pipeserver lost under --survive-host-loss): no signal from now on,
  // nothing more received. A frame it died sending never arrives whole.
  void lose();
  bool lost() const { return lost_; }

 private:
  // Completes the posted receive if it is done (rebuilding its frame) and posts the next; true
  // when one completed. Throws std::runtime_error for a frame that does not decode.
  bool poll();
  void post();
  // A frame: its message's bytes, the sequence number first, and where its rows start (a whole
  // frame's are where they arrived; a decoded one's are a copy of the decoder's).
  struct Held {
    std::vector<std::uint8_t> bytes;
    std::size_t rows = 0;
  };
  static std::uint64_t sequence_of(const Held& m);
  std::vector<std::uint8_t> spare_buffer();

  int source_;
  int width_, height_;
  std::size_t frame_bytes_;
  std::size_t buffer_bytes_;          // the largest message, and every buffer's size
  std::vector<std::uint8_t> posted_;  // sequence number, then the encoded frame
  FrameDeltaDecoder decoder_;
  bool decoder_behind_ = false;  // whole frames were taken as they arrived, not decoded
  MPI_Request request_ = MPI_REQUEST_NULL;
  std::deque<Held> arrived_;  // oldest first
  std::vector<std::vector<std::uint8_t>> spare_;
  std::optional<Held> current_;
  bool lost_ = false;
};

}  // namespace l2
