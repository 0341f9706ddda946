#include "mpi_link/mpi_dvi_link.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <thread>

#include "mpi_link/mpi_wire.hpp"

namespace l2 {
namespace {

constexpr std::size_t kSequenceBytes = sizeof(std::uint64_t);

void check_link(int code, const char* what, int peer) {
  if (code != MPI_SUCCESS)
    throw std::runtime_error(fmt::format("DVI link over MPI: {} with rank {} failed", what, peer));
}

}  // namespace

MpiDviSender::MpiDviSender(std::vector<ColumnFeed> columns, int coordinator_rank, int width,
                           int height, std::shared_ptr<SentBytes> bytes_sent)
    : coordinator_(coordinator_rank), bytes_sent_(std::move(bytes_sent)) {
  for (ColumnFeed& c : columns) {
    const auto same = std::find_if(streams_.begin(), streams_.end(), [&](const Stream& s) {
      return s.codec == c.codec && s.blank == c.blank;
    });
    if (same != streams_.end()) {
      same->ranks.push_back(c.rank);
      continue;
    }
    streams_.push_back(
        {c.codec, std::move(c.blank), {c.rank}, FrameDeltaEncoder(width, height, c.codec), {}});
  }
  const std::size_t frame = static_cast<std::size_t>(width) * height * kDviBytesPerPixel;
  for (Stream& s : streams_) {
    if (s.codec != LinkCodec::Whole || !s.blank.empty()) continue;
    in_place_ = &s;
    const std::size_t prefix = whole_frame_prefix_bytes(height);
    s.message.resize(kSequenceBytes + prefix + frame);
    write_whole_frame_prefix(width, height, std::span(s.message).subspan(kSequenceBytes));
    frame_ = std::span(s.message).subspan(kSequenceBytes + prefix);
    return;
  }
  own_frame_.resize(frame);
  frame_ = own_frame_;
}

std::span<std::uint8_t> MpiDviSender::back_frame() {
  return frame_;
}

std::uint64_t MpiDviSender::publish() {
  ++sequence_;
  std::vector<MPI_Request> requests;
  for (Stream& s : streams_) {
    if (&s != in_place_) {
      const std::span<const std::uint8_t> encoded = s.encoder.encode(frame_, s.blank);
      s.message.resize(kSequenceBytes + encoded.size());
      std::memcpy(s.message.data() + kSequenceBytes, encoded.data(), encoded.size());
    }
    std::memcpy(s.message.data(), &sequence_, kSequenceBytes);
    for (const int rank : s.ranks) {
      requests.emplace_back();
      check_link(MPI_Isend(s.message.data(), static_cast<int>(s.message.size()), MPI_BYTE, rank,
                           mpi_wire::kFrame, MPI_COMM_WORLD, &requests.back()),
                 "sending a frame", rank);
      bytes_sent_->raw += frame_.size();
      bytes_sent_->wire += s.message.size();
      if (sequence_ == 1) bytes_sent_->first_wire += s.message.size();
    }
  }
  check_link(MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE),
             "sending a frame", streams_.empty() ? -1 : streams_.front().ranks.front());
  mpi_wire::send({static_cast<std::int64_t>(sequence_)}, coordinator_, mpi_wire::kNotice);
  return sequence_;
}

MpiDviReceiver::MpiDviReceiver(int source_rank, int width, int height)
    : source_(source_rank),
      width_(width),
      height_(height),
      frame_bytes_(static_cast<std::size_t>(width) * height * kDviBytesPerPixel),
      buffer_bytes_(kSequenceBytes + max_frame_delta_bytes(width, height)),
      posted_(buffer_bytes_),
      decoder_(width, height) {
  post();
}

MpiDviReceiver::~MpiDviReceiver() {
  if (request_ != MPI_REQUEST_NULL) {
    // Waited for, not freed: a receive still in flight would write into the freed buffer
    // (a column resumed after a stop, ending while its pipeservers still send).
    MPI_Cancel(&request_);
    MPI_Wait(&request_, MPI_STATUS_IGNORE);
  }
}

void MpiDviReceiver::post() {
  check_link(MPI_Irecv(posted_.data(), static_cast<int>(posted_.size()), MPI_BYTE, source_,
                       mpi_wire::kFrame, MPI_COMM_WORLD, &request_),
             "receiving a frame", source_);
}

std::vector<std::uint8_t> MpiDviReceiver::spare_buffer() {
  if (spare_.empty()) return std::vector<std::uint8_t>(buffer_bytes_);
  std::vector<std::uint8_t> b = std::move(spare_.back());
  spare_.pop_back();
  return b;
}

bool MpiDviReceiver::poll() {
  if (lost_) return false;
  int done = 0;
  MPI_Status status;
  check_link(MPI_Test(&request_, &done, &status), "receiving a frame", source_);
  if (!done) return false;
  int count = 0;
  MPI_Get_count(&status, MPI_BYTE, &count);
  const auto n = static_cast<std::size_t>(count);
  const std::span<const std::uint8_t> message =
      std::span(posted_).subspan(std::min(n, kSequenceBytes), n - std::min(n, kSequenceBytes));
  const auto refuse = [&](const std::string& why) {
    return std::runtime_error(fmt::format(
        "DVI link over MPI: rank {} sent a frame that does not decode: {}", source_, why));
  };
  if (n < kSequenceBytes) throw refuse(fmt::format("{} bytes", n));
  if (decoder_.check_whole(message).ok()) {
    // Routed where it arrived; the receive goes on into another buffer.
    arrived_.push_back({std::move(posted_), kSequenceBytes + whole_frame_prefix_bytes(height_)});
    posted_ = spare_buffer();
    decoder_behind_ = true;
  } else {
    // Every change is applied as it arrives, even to a frame dropped later: the next builds on
    // it. A sender's frames to one column all travel one way, so none follows a whole frame.
    if (decoder_behind_) throw refuse("changes after whole frames");
    if (const Status s = decoder_.decode(message); !s.ok()) throw refuse(s.reason());
    Held frame{spare_buffer(), kSequenceBytes};
    std::memcpy(frame.bytes.data(), posted_.data(), kSequenceBytes);
    std::memcpy(frame.bytes.data() + kSequenceBytes, decoder_.frame().data(), frame_bytes_);
    arrived_.push_back(std::move(frame));
  }
  post();
  return true;
}

std::uint64_t MpiDviReceiver::sequence_of(const Held& m) {
  std::uint64_t s = 0;
  std::memcpy(&s, m.bytes.data(), kSequenceBytes);
  return s;
}

void MpiDviReceiver::take(std::uint64_t sequence, const std::function<void()>& watch) {
  if (sequence == 0 || (current_ && sequence_of(*current_) == sequence)) return;
  while (!lost_) {
    while (poll()) {
    }
    while (!arrived_.empty() && sequence_of(arrived_.front()) < sequence) {
      spare_.push_back(std::move(arrived_.front().bytes));
      arrived_.pop_front();
    }
    if (!arrived_.empty()) break;
    watch();
    std::this_thread::sleep_for(std::chrono::microseconds(50));
  }
  if (lost_) return;
  if (current_) spare_.push_back(std::move(current_->bytes));
  current_ = std::move(arrived_.front());
  arrived_.pop_front();
}

void MpiDviReceiver::lose() {
  if (lost_) return;
  lost_ = true;
  if (request_ != MPI_REQUEST_NULL) {
    // Not waited for: a frame its sender died sending would never end the wait. Its buffer is
    // left to the process's end, in case MPI still writes into it.
    MPI_Cancel(&request_);
    MPI_Request_free(&request_);
    static_cast<void>(new std::vector<std::uint8_t>(std::move(posted_)));
  }
  arrived_.clear();
  current_.reset();
}

std::optional<FrameView> MpiDviReceiver::latest() {
  if (!current_) return std::nullopt;
  FrameView v;
  v.pixels = current_->bytes.data() + current_->rows;
  v.width = width_;
  v.height = height_;
  v.stride = static_cast<std::size_t>(width_) * kDviBytesPerPixel;
  v.sequence = sequence_of(*current_);
  return v;
}

}  // namespace l2
