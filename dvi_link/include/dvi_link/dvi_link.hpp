// The DVI link on one machine: a pipeserver's scanned-out frame travels to the emulator through
// a named POSIX shared-memory segment. One writer (the pipeserver) and one reader (the emulator
// input) per link. Frames are 24-bit RGB, rows top to bottom (spec §1).
//
// Three frame slots form a lock-free triple buffer: the writer owns one slot (the back frame),
// the reader owns one (the frame it is looking at), and the third holds the latest published
// frame. publish() and latest() swap slots with one atomic exchange, so the writer never waits
// and never touches the slot the reader holds: a reader can look at a frame in place, without
// copying, and it can never be torn. (Two slots cannot give both: the writer would have to wait
// for the reader, or overwrite the frame under it.)
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

namespace l2 {

class DviLinkError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

inline constexpr int kDviBytesPerPixel = 3;
inline constexpr int kDviMaxDimension = 8192;

// "/l2-<pid>-<suffix>": segment names owned by this process, so parallel runs and tests never
// collide. `suffix` must not contain '/'.
std::string dvi_link_name(std::string_view suffix);

// Removes a segment left behind by a process that died (shm_unlink). Returns true when there
// was one. Throws DviLinkError for an invalid name or when unlinking fails for another reason
// than "does not exist".
bool remove_stale(const std::string& name);

namespace detail {
struct LinkHeader;
// One end's hold on a segment, given up exactly once: what the end does on leaving (the writer
// unlinks the name, the reader frees its place in the header), then the mapping unmapped.
// Move-only, and the one hand-written move of the link: a moved-from Segment holds nothing, so
// both ends move by their defaults.
class Segment {
 public:
  enum class Leaving { kNothing, kUnlink, kDetach };

  Segment() = default;
  Segment(std::string name, Leaving leaving) : name_(std::move(name)), leaving_(leaving) {}
  Segment(Segment&& other) noexcept;
  Segment& operator=(Segment&& other) noexcept;
  Segment(const Segment&) = delete;
  Segment& operator=(const Segment&) = delete;
  ~Segment() { release(); }

  // Maps `size` bytes of the open segment `fd`; throws DviLinkError naming the segment.
  void map(int fd, std::size_t size);
  // From now on leaving does `leaving`.
  void leave_by(Leaving leaving) { leaving_ = leaving; }

  const std::string& name() const { return name_; }
  LinkHeader& header() const { return *static_cast<LinkHeader*>(base_); }
  std::uint8_t* bytes() const { return static_cast<std::uint8_t*>(base_); }

 private:
  void release() noexcept;

  std::string name_;
  Leaving leaving_ = Leaving::kNothing;
  void* base_ = nullptr;
  std::size_t size_ = 0;
};
}  // namespace detail

// The DVI link behind one interface, sender side: the pipeserver draws its scanned-out frame
// into the back frame and hands it over. Shared memory (DviLinkWriter) is one implementation.
class DviSender {
 public:
  virtual ~DviSender() = default;
  virtual std::span<std::uint8_t> back_frame() = 0;
  // Hands the back frame over; returns its sequence number (1, 2, ...).
  virtual std::uint64_t publish() = 0;
};

// Pipeserver side. Creates the segment and unlinks it again on destruction.
class DviLinkWriter final : public DviSender {
 public:
  // Creates segment `name` for width x height frames, all slots black. If a segment of that
  // name exists and the process that created it is dead, it is replaced; if that process is
  // alive, or the segment has no complete DVI link header, this is an error (a process that
  // died but was not yet reaped by its parent still counts as alive).
  // Errors: DviLinkError "DVI link <name>: ...".
  static DviLinkWriter create(const std::string& name, int width, int height);

  // The frame being drawn: height rows of width * 3 bytes, row 0 on top. It keeps the contents
  // of an older frame (not the one just published), so draw every pixel.
  std::span<std::uint8_t> back_frame() override;
  std::span<std::uint8_t> back_row(int y);
  // Hands the back frame to the reader and returns its sequence number (1, 2, ...). Throws
  // DviLinkError when the slot handed back does not exist (the header was written over).
  std::uint64_t publish() override;

  const std::string& name() const { return segment_.name(); }
  int width() const { return width_; }
  int height() const { return height_; }
  std::size_t stride() const { return static_cast<std::size_t>(width_) * kDviBytesPerPixel; }

 private:
  DviLinkWriter() = default;

  detail::Segment segment_;
  int width_ = 0;
  int height_ = 0;
  // Kept here, not read back from the shared header, which another process can overwrite.
  std::uint64_t slot_pitch_ = 0;
  int back_ = 0;
  std::uint64_t sequence_ = 0;
};

// A published frame, in place in shared memory. Valid until the next latest() or until the
// reader goes away.
struct FrameView {
  const std::uint8_t* pixels = nullptr;
  std::size_t stride = 0;  // bytes from one row to the next
  int width = 0;
  int height = 0;
  std::uint64_t sequence = 0;  // 1 for the first frame published, then +1 per publish()

  std::span<const std::uint8_t> row(int y) const {
    return {pixels + static_cast<std::size_t>(y) * stride,
            static_cast<std::size_t>(width) * kDviBytesPerPixel};
  }
};

// Receiver side, one input: the latest frame it carries. Shared memory (DviLinkReader) is one
// implementation.
class DviReceiver {
 public:
  virtual ~DviReceiver() = default;
  // The newest frame handed over; nullopt before the first. Again without a new one: the same.
  virtual std::optional<FrameView> latest() = 0;
};

// Emulator side. One reader per segment at a time.
class DviLinkReader final : public DviReceiver {
 public:
  // Opens an existing segment and checks its header and size. Errors: DviLinkError
  // "DVI link <name>: ..." (no such segment, not a DVI link, version, size, already has a
  // live reader).
  static DviLinkReader open(const std::string& name);

  // The newest published frame; nullopt before the first publish(). Calling it again without a
  // new publish returns the same frame (same sequence number). Throws DviLinkError when the
  // header names a slot that does not exist (written over by another process).
  std::optional<FrameView> latest() override;
  // Whether the process that created the segment still runs.
  bool writer_alive() const;

  const std::string& name() const { return segment_.name(); }
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  DviLinkReader() = default;

  detail::Segment segment_;
  int width_ = 0;
  int height_ = 0;
  // Checked against the segment's size at open() and kept: the header is not read again for
  // addresses, since another process can overwrite it.
  std::uint64_t slot_pitch_ = 0;
  int front_ = 0;
};

}  // namespace l2
