#include "dvi_link/dvi_link.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstddef>
#include <cstring>
#include <utility>

#include <fmt/format.h>

#include "base/fd.hpp"

namespace l2 {
namespace detail {

// The segment starts with this header, then three frame slots. Only lock-free atomics live in
// shared memory: a lock-based std::atomic would hide a process-local lock.
struct LinkHeader {
  std::atomic<std::uint32_t> magic;  // stored last by the creator: the header is complete
  std::uint32_t version;
  std::int32_t width;
  std::int32_t height;
  std::int32_t bytes_per_pixel;
  std::uint32_t writer_slot;  // slot the writer draws into (owned by the writer)
  std::uint64_t stride;
  std::uint64_t frame_bytes;
  std::uint64_t slot_offset;  // of slot 0; slot i at slot_offset + i * slot_pitch
  std::uint64_t slot_pitch;
  std::uint64_t total_bytes;
  std::atomic<std::int32_t> writer_pid;
  std::atomic<std::int32_t> reader_pid;  // 0: no reader attached
  // Index of the latest published slot, plus kFresh while the reader has not taken it.
  std::atomic<std::uint32_t> middle;
  std::uint32_t reader_slot;             // slot the reader holds (owned by the attached reader)
  std::atomic<std::uint64_t> published;  // frames published so far
  // Sequence number of the frame in each slot, written by whoever owns the slot's pixels.
  std::uint64_t slot_sequence[3];
};

// The layout is shared between processes (version 1): pinned, so that a change to it is a
// change of kVersion and not an accident. The tests write these offsets to play a process
// that corrupts the header.
static_assert(offsetof(LinkHeader, stride) == 24 && offsetof(LinkHeader, slot_pitch) == 48 &&
              offsetof(LinkHeader, total_bytes) == 56 && offsetof(LinkHeader, middle) == 72 &&
              offsetof(LinkHeader, reader_slot) == 76);

}  // namespace detail

namespace {

using detail::LinkHeader;
using detail::Segment;

static_assert(std::atomic<std::uint32_t>::is_always_lock_free);
static_assert(std::atomic<std::int32_t>::is_always_lock_free);
static_assert(std::atomic<std::uint64_t>::is_always_lock_free);

constexpr std::uint32_t kMagic = 0x4C32'4456;  // "L2DV"
constexpr std::uint32_t kVersion = 1;
constexpr std::uint32_t kFresh = 4;
constexpr std::uint32_t kSlotMask = 3;
constexpr std::uint64_t kHeaderBytes = 4096;  // one page, so slot 0 starts page-aligned
constexpr std::uint64_t kSlotAlign = 64;
static_assert(sizeof(LinkHeader) <= kHeaderBytes);

[[noreturn]] void fail(const std::string& name, std::string_view what) {
  throw DviLinkError(fmt::format("DVI link {}: {}", name, what));
}
[[noreturn]] void fail_errno(const std::string& name, std::string_view what, int error) {
  fail(name, fmt::format("{}: {}", what, std::strerror(error)));
}

void check_name(const std::string& name) {
  if (name.size() < 2 || name.size() > 255 || name[0] != '/' ||
      name.find('/', 1) != std::string::npos) {
    throw DviLinkError(fmt::format(
        "DVI link name \"{}\" is invalid: it must be '/' followed by 1 to 254 characters "
        "without '/'",
        name));
  }
}

// A slot index read back from shared memory, where another process can write anything: only
// slots 0..2 exist, and kSlotMask lets 3 through.
int checked_slot(const std::string& name, std::uint32_t value, std::string_view field) {
  const std::uint32_t slot = value & kSlotMask;
  if (slot > 2) fail(name, fmt::format("corrupt header: {} names slot {} of 3", field, slot));
  return static_cast<int>(slot);
}

// Where slot `slot`'s pixels start.
std::uint8_t* slot_pixels(const Segment& map, int slot, std::uint64_t pitch) {
  return map.bytes() + kHeaderBytes + static_cast<std::uint64_t>(slot) * pitch;
}

bool process_alive(std::int32_t pid) {
  return pid > 0 && (::kill(pid, 0) == 0 || errno == EPERM);
}

std::uint64_t slot_pitch(std::uint64_t frame_bytes) {
  return (frame_bytes + kSlotAlign - 1) / kSlotAlign * kSlotAlign;
}

// Pid of the writer of an existing segment; -1 when it holds no complete DVI link header
// (another creator may be half-way through, or it is not ours), 0 when it has vanished since.
std::int32_t existing_writer(const std::string& name) {
  const Fd fd(
      ::shm_open(name.c_str(), O_RDWR, 0));  // closed on every path; the mapping outlives it
  if (!fd) return 0;
  struct stat st {};
  if (::fstat(fd.get(), &st) != 0 || static_cast<std::uint64_t>(st.st_size) < kHeaderBytes) {
    return -1;
  }
  Segment peek(name, Segment::Leaving::kNothing);
  peek.map(fd.get(), kHeaderBytes);
  if (peek.header().magic.load(std::memory_order_acquire) != kMagic) return -1;
  return peek.header().writer_pid.load();
}

// Creates the segment exclusively; replaces one whose creator is dead.
int create_segment(const std::string& name) {
  for (int attempt = 0; attempt < 2; ++attempt) {
    const int fd = ::shm_open(name.c_str(), O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
    if (fd >= 0) return fd;
    if (errno != EEXIST) fail_errno(name, "cannot create shared-memory segment", errno);
    const std::int32_t pid = existing_writer(name);
    if (pid < 0) {
      // Named as a user can remove it (shm_open's names live in /dev/shm on Linux).
      fail(name, fmt::format("already exists and is not a complete DVI link (if it was left "
                             "behind, remove /dev/shm{})",
                             name));
    }
    if (process_alive(pid)) {
      fail(name, fmt::format("already exists and is in use by process {}", pid));
    }
    remove_stale(name);
  }
  fail(name, "cannot create shared-memory segment: it keeps reappearing");
}

}  // namespace

namespace detail {

Segment::Segment(Segment&& other) noexcept
    : name_(std::exchange(other.name_, {})),
      leaving_(std::exchange(other.leaving_, Leaving::kNothing)),
      base_(std::exchange(other.base_, nullptr)),
      size_(std::exchange(other.size_, 0)) {}

Segment& Segment::operator=(Segment&& other) noexcept {
  if (this != &other) {
    release();
    name_ = std::exchange(other.name_, {});
    leaving_ = std::exchange(other.leaving_, Leaving::kNothing);
    base_ = std::exchange(other.base_, nullptr);
    size_ = std::exchange(other.size_, 0);
  }
  return *this;
}

void Segment::map(int fd, std::size_t size) {
  void* base = ::mmap(nullptr, size, PROT_READ | PROT_WRITE, MAP_SHARED, fd, 0);
  if (base == MAP_FAILED) fail_errno(name_, "cannot map", errno);
  base_ = base;
  size_ = size;
}

void Segment::release() noexcept {
  switch (std::exchange(leaving_, Leaving::kNothing)) {
    case Leaving::kNothing:
      break;
    case Leaving::kUnlink:
      // Readers that still have the segment mapped keep reading it; the name is gone at once.
      ::shm_unlink(name_.c_str());
      break;
    case Leaving::kDetach:
      // Release: a later reader sees reader_slot as we left it.
      header().reader_pid.store(0, std::memory_order_release);
      break;
  }
  if (base_ != nullptr) ::munmap(base_, size_);
  base_ = nullptr;
  size_ = 0;
}

}  // namespace detail

std::string dvi_link_name(std::string_view suffix) {
  std::string name = fmt::format("/l2-{}-{}", ::getpid(), suffix);
  check_name(name);
  return name;
}

bool remove_stale(const std::string& name) {
  check_name(name);
  if (::shm_unlink(name.c_str()) == 0) return true;
  if (errno == ENOENT) return false;
  fail_errno(name, "cannot remove", errno);
}

// ---- writer ----------------------------------------------------------------------------------

DviLinkWriter DviLinkWriter::create(const std::string& name, int width, int height) {
  check_name(name);
  if (width < 1 || height < 1 || width > kDviMaxDimension || height > kDviMaxDimension) {
    fail(name, fmt::format("frame size {}x{} is outside 1x1 .. {}x{}", width, height,
                           kDviMaxDimension, kDviMaxDimension));
  }
  const std::uint64_t stride = static_cast<std::uint64_t>(width) * kDviBytesPerPixel;
  const std::uint64_t frame_bytes = stride * static_cast<std::uint64_t>(height);
  const std::uint64_t pitch = slot_pitch(frame_bytes);
  const std::uint64_t total = kHeaderBytes + 3 * pitch;

  const Fd fd(create_segment(name));
  DviLinkWriter writer;
  // From here on the segment is unlinked on any error.
  writer.segment_ = Segment(name, Segment::Leaving::kUnlink);
  if (::ftruncate(fd.get(), static_cast<off_t>(total)) != 0) {
    fail_errno(name, fmt::format("cannot size to {} bytes", total), errno);
  }
  writer.segment_.map(fd.get(), total);
  // ftruncate zero-filled everything: all slots are black, all counters 0.
  LinkHeader& h = writer.segment_.header();
  h.version = kVersion;
  h.width = width;
  h.height = height;
  h.bytes_per_pixel = kDviBytesPerPixel;
  h.stride = stride;
  h.frame_bytes = frame_bytes;
  h.slot_offset = kHeaderBytes;
  h.slot_pitch = pitch;
  h.total_bytes = total;
  h.writer_slot = 0;
  h.middle.store(1, std::memory_order_relaxed);
  h.reader_slot = 2;
  h.writer_pid.store(::getpid(), std::memory_order_relaxed);
  h.magic.store(kMagic, std::memory_order_release);
  writer.width_ = width;
  writer.height_ = height;
  writer.slot_pitch_ = pitch;
  writer.back_ = 0;
  return writer;
}

std::span<std::uint8_t> DviLinkWriter::back_frame() {
  return {slot_pixels(segment_, back_, slot_pitch_), stride() * static_cast<std::size_t>(height_)};
}

std::span<std::uint8_t> DviLinkWriter::back_row(int y) {
  if (y < 0 || y >= height_) {
    fail(name(), fmt::format("row {} is outside the frame (height {})", y, height_));
  }
  return back_frame().subspan(static_cast<std::size_t>(y) * stride(), stride());
}

std::uint64_t DviLinkWriter::publish() {
  LinkHeader& h = segment_.header();
  h.slot_sequence[back_] = ++sequence_;
  // Release: the pixels and sequence above become visible to the reader that takes this slot.
  // Acquire: the slot we get back was released by the reader, which no longer looks at it.
  const std::uint32_t old =
      h.middle.exchange(static_cast<std::uint32_t>(back_) | kFresh, std::memory_order_acq_rel);
  back_ = checked_slot(name(), old, "the latest frame");
  h.writer_slot = static_cast<std::uint32_t>(back_);
  h.published.store(sequence_, std::memory_order_release);
  return sequence_;
}

// ---- reader ----------------------------------------------------------------------------------

DviLinkReader DviLinkReader::open(const std::string& name) {
  check_name(name);
  const Fd fd(::shm_open(name.c_str(), O_RDWR | O_CLOEXEC, 0));
  if (!fd) fail_errno(name, "cannot open shared-memory segment", errno);
  struct stat st {};
  if (::fstat(fd.get(), &st) != 0) fail_errno(name, "cannot stat", errno);
  const auto size = static_cast<std::uint64_t>(st.st_size);
  if (size < kHeaderBytes) {
    fail(name, fmt::format("segment is {} bytes, too small for a DVI link header", size));
  }
  DviLinkReader reader;
  reader.segment_ = Segment(name, Segment::Leaving::kNothing);
  reader.segment_.map(fd.get(), size);
  const LinkHeader& h = reader.segment_.header();
  const std::uint32_t magic = h.magic.load(std::memory_order_acquire);
  if (magic != kMagic) fail(name, fmt::format("not a DVI link (magic {:#010x})", magic));
  if (h.version != kVersion) {
    fail(name, fmt::format("version {} is not the supported version {}", h.version, kVersion));
  }
  // Everything the reader will use to address memory is read once, checked against the real
  // size (without overflow: 3 * a huge pitch can wrap to the right total) and kept.
  const std::int32_t width = h.width, height = h.height;
  const std::uint64_t pitch = h.slot_pitch, total = h.total_bytes;
  const bool dims_ok = width >= 1 && height >= 1 && width <= kDviMaxDimension &&
                       height <= kDviMaxDimension && h.bytes_per_pixel == kDviBytesPerPixel;
  const std::uint64_t stride = static_cast<std::uint64_t>(width) * kDviBytesPerPixel;
  const std::uint64_t frame_bytes = stride * static_cast<std::uint64_t>(height);
  if (!dims_ok || h.stride != stride || h.frame_bytes != frame_bytes ||
      h.slot_offset != kHeaderBytes || pitch < frame_bytes || pitch > size / 3 ||
      total != kHeaderBytes + 3 * pitch) {
    fail(name, "corrupt header");
  }
  if (total != size) {
    fail(name, fmt::format("header declares {} bytes but the segment is {} bytes", total, size));
  }
  reader.width_ = width;
  reader.height_ = height;
  reader.slot_pitch_ = pitch;

  // Attach as the one reader; a reader that died does not block a new one.
  LinkHeader& hw = reader.segment_.header();
  std::int32_t current = hw.reader_pid.load(std::memory_order_acquire);
  for (;;) {
    if (current != 0 && process_alive(current)) {
      fail(name, fmt::format("already has a reader (process {})", current));
    }
    if (hw.reader_pid.compare_exchange_weak(current, ::getpid(), std::memory_order_acq_rel)) {
      break;
    }
  }
  reader.segment_.leave_by(Segment::Leaving::kDetach);  // attached: free the place on leaving
  reader.front_ = checked_slot(name, hw.reader_slot, "the reader's frame");
  return reader;
}

std::optional<FrameView> DviLinkReader::latest() {
  LinkHeader& h = segment_.header();
  if (h.middle.load(std::memory_order_relaxed) & kFresh) {
    // Hand back the slot we held and take the newest; see publish() for the ordering.
    const std::uint32_t old =
        h.middle.exchange(static_cast<std::uint32_t>(front_), std::memory_order_acq_rel);
    front_ = checked_slot(name(), old, "the latest frame");
    h.reader_slot = static_cast<std::uint32_t>(front_);
  }
  const std::uint64_t sequence = h.slot_sequence[front_];
  if (sequence == 0) return std::nullopt;
  return FrameView{slot_pixels(segment_, front_, slot_pitch_),
                   static_cast<std::size_t>(width_) * kDviBytesPerPixel, width_, height_, sequence};
}

bool DviLinkReader::writer_alive() const {
  return process_alive(segment_.header().writer_pid.load(std::memory_order_relaxed));
}

}  // namespace l2
