#include "cluster/mpi_dvi_link.hpp"

#include <fmt/format.h>

#include <cstring>
#include <stdexcept>
#include <thread>

#include "cluster/mpi_wire.hpp"

namespace l2 {
namespace {

constexpr std::size_t kSequenceBytes = sizeof(std::uint64_t);

void check_link(int code, const char* what, int peer) {
  if (code != MPI_SUCCESS)
    throw std::runtime_error(fmt::format("DVI link over MPI: {} with rank {} failed", what, peer));
}

}  // namespace

MpiDviSender::MpiDviSender(std::vector<int> column_ranks, int coordinator_rank, int width,
                           int height, std::shared_ptr<std::uint64_t> bytes_sent)
    : columns_(std::move(column_ranks)),
      coordinator_(coordinator_rank),
      message_(kSequenceBytes + static_cast<std::size_t>(width) * height * kDviBytesPerPixel),
      bytes_sent_(std::move(bytes_sent)) {}

std::span<std::uint8_t> MpiDviSender::back_frame() {
  return std::span<std::uint8_t>(message_).subspan(kSequenceBytes);
}

std::uint64_t MpiDviSender::publish() {
  ++sequence_;
  std::memcpy(message_.data(), &sequence_, kSequenceBytes);
  std::vector<MPI_Request> requests(columns_.size());
  for (std::size_t i = 0; i < columns_.size(); ++i) {
    check_link(MPI_Isend(message_.data(), static_cast<int>(message_.size()), MPI_BYTE, columns_[i],
                         mpi_wire::kFrame, MPI_COMM_WORLD, &requests[i]),
               "sending a frame", columns_[i]);
  }
  check_link(MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE),
             "sending a frame", columns_.empty() ? -1 : columns_.front());
  *bytes_sent_ += message_.size() * columns_.size();
  mpi_wire::send({static_cast<std::int64_t>(sequence_)}, coordinator_, mpi_wire::kNotice);
  return sequence_;
}

MpiDviReceiver::MpiDviReceiver(int source_rank, int width, int height)
    : source_(source_rank),
      width_(width),
      height_(height),
      bytes_(kSequenceBytes + static_cast<std::size_t>(width) * height * kDviBytesPerPixel) {
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
  if (spare_.empty()) {
    posted_.assign(bytes_, 0);
  } else {
    posted_ = std::move(spare_.back());
    spare_.pop_back();
  }
  check_link(MPI_Irecv(posted_.data(), static_cast<int>(posted_.size()), MPI_BYTE, source_,
                       mpi_wire::kFrame, MPI_COMM_WORLD, &request_),
             "receiving a frame", source_);
}

bool MpiDviReceiver::poll() {
  int done = 0;
  MPI_Status status;
  check_link(MPI_Test(&request_, &done, &status), "receiving a frame", source_);
  if (!done) return false;
  int count = 0;
  MPI_Get_count(&status, MPI_BYTE, &count);
  if (static_cast<std::size_t>(count) != bytes_)
    throw std::runtime_error(fmt::format("DVI link over MPI: rank {} sent {} bytes, expected {}",
                                         source_, count, bytes_));
  arrived_.push_back(std::move(posted_));
  post();
  return true;
}

std::uint64_t MpiDviReceiver::sequence_of(const std::vector<std::uint8_t>& m) {
  std::uint64_t s = 0;
  std::memcpy(&s, m.data(), kSequenceBytes);
  return s;
}

void MpiDviReceiver::take(std::uint64_t sequence, const std::function<void()>& watch) {
  if (sequence == 0 || (current_ && sequence_of(*current_) == sequence)) return;
  for (;;) {
    while (poll()) {
    }
    while (!arrived_.empty() && sequence_of(arrived_.front()) < sequence) {
      spare_.push_back(std::move(arrived_.front()));
      arrived_.pop_front();
    }
    if (!arrived_.empty()) break;
    watch();
    std::this_thread::sleep_for(std::chrono::microseconds(50));
  }
  if (current_) spare_.push_back(std::move(*current_));
  current_ = std::move(arrived_.front());
  arrived_.pop_front();
}

std::optional<FrameView> MpiDviReceiver::latest() {
  if (!current_) return std::nullopt;
  FrameView v;
  v.pixels = current_->data() + kSequenceBytes;
  v.width = width_;
  v.height = height_;
  v.stride = static_cast<std::size_t>(width_) * kDviBytesPerPixel;
  v.sequence = sequence_of(*current_);
  return v;
}

}  // namespace l2
