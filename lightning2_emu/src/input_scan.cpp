// Scanning one input frame (spec §3) into runs of strips per display band, for Router::scan().
//
// A packed frame repeats itself down the scanlines of a row of tiles: the same headers at the
// same columns, each COPY one display row further down. So a scanline is first checked against
// the last one: if every header holds exactly the value predicted for it (48 raw bits compared,
// check bits included), the scanline extends the same runs and counts the same as the last one,
// with no decoding. Any other scanline is parsed in full. The fast path is taken only where the
// full parse is known to give the same result: the last scanline was parsed without error, and
// every header it repeats is clean (see kNever).
#include <algorithm>

#include "pixel_copy.hpp"
#include "router_detail.hpp"
#include "strip_headers/scanline_parser.hpp"

namespace l2::router_detail {
namespace {

// No scanline holds this value (a raw header has 48 bits): a seen header that cannot repeat, so
// the next scanline is parsed in full. Its run ends with its band or display, or it was clipped
// or went to no display, which must be counted again.
constexpr std::uint64_t kNever = ~std::uint64_t{0};

// The raw header one display row further down: the y field plus one, check bits recomputed.
// Only asked for rows below 4095, so the field does not carry over.
std::uint64_t one_row_down(std::uint64_t value) {
  const std::uint64_t message = (value >> 3) + (std::uint64_t{1} << (header_bits::kYShift - 3));
  return message << 3 | crc3(message);
}

class Scanner {
 public:
  Scanner(const InputFrame& frame, const std::vector<Target>& targets, Layout& out,
          ScanScratch& scratch)
      : out_(out), sc_(scratch), targets_(targets), f_(frame) {}

  void scan(int input) {
    for (auto& band : out_.bands) band.clear();
    sc_.seen.clear();
    out_.others.clear();
    out_.parity_at = -1;
    out_.composited = 0;
    repeatable_ = false;
    for (int y = 0; y < f_.height; ++y) {
      const std::uint8_t* row = f_.row(y);
      if (black_start(row)) {  // END at column 0: most scanlines below the packed tiles
        sc_.seen.clear();
        remember_end(y, 0);
        repeatable_ = false;
      } else if (!(repeatable_ && repeat(row, y))) {
        parse(row, y);
      }
      prefetch_headers(y + kAhead);
    }
    order_runs();
    store_stats(input);
  }

 private:
  static constexpr int kAhead = 4;     // scanlines ahead whose header lines are fetched
  static constexpr int kTracked = 32;  // headers of a scanline fetched ahead, at most

  bool black_start(const std::uint8_t* row) const {
    const int bpp = f_.bytes_per_pixel;
    return f_.width >= kHeaderPixels && (row[0] | row[1] | row[2]) == 0 &&
           (row[bpp] | row[bpp + 1] | row[bpp + 2]) == 0;
  }

  std::uint64_t raw_header(const std::uint8_t* row, int x) const {
    const std::uint8_t* p = row + static_cast<std::ptrdiff_t>(x) * f_.bytes_per_pixel;
    return header_value(p, p + f_.bytes_per_pixel);
  }

  // The fast path: true when the scanline repeats the last one, which it then extends.
  bool repeat(const std::uint8_t* row, int y) {
    for (const SeenHeader& h : sc_.seen) {
      if (raw_header(row, h.x) != h.value) return false;
      if (h.ext && raw_header(row, h.x + kHeaderPixels) != h.ext) return false;
    }
    for (SeenHeader& h : sc_.seen) {
      if (h.list < 0) {  // a SKIP or an END (a header that cannot repeat is never seen again)
        if (h.value >> header_bits::kOpShift == static_cast<int>(StripOp::Skip)) {
          ++skips_;
          remember_header(y, h.x, h.value);
        } else {
          remember_end(y, h.x);
        }
        continue;
      }
      ++out_.bands[h.list][h.run].rows;
      ++found_[static_cast<int>(h.kind)];
      ++routed_;
      h.value = ++h.next_y <= h.last_y ? one_row_down(h.value) : kNever;
    }
    return true;
  }

  // The full parse of a scanline, remembering its headers for the next one.
  void parse(const std::uint8_t* row, int y) {
    sc_.seeing.clear();
    next_seen_ = 0;
    const std::uint64_t errors_before = errors_.total();
    int next_header = 0;  // where the parser looks for the header after the last strip
    parse_scanline(row, f_.width, f_.bytes_per_pixel, errors_, [&](const ParsedStrip& s) {
      const int x = s.header_x();
      next_header = s.next_header_x();
      parities_ |= static_cast<std::uint8_t>(s.header.frame ? 2 : 1);
      if (out_.parity_at < 0) out_.parity_at = offset(y, x);
      if (s.header.op == StripOp::Skip) {
        ++skips_;
        sc_.seeing.push_back({x, raw_header(row, x), -1, 0, 0, 0});
        remember_header(y, x, raw_header(row, x));
        return true;
      }
      ++found_[static_cast<int>(kind_of(s))];
      route_strip(s, row, y);
      return true;
    });
    // The parser stopped at an END (it counts any other stop as an error) or at the row's end.
    if (next_header <= f_.width - kHeaderPixels) {
      sc_.seeing.push_back({next_header, raw_header(row, next_header), -1, 0, 0, 0});
      remember_end(y, next_header);  // or an error, which leaves no layout
    }
    std::swap(sc_.seen, sc_.seeing);
    repeatable_ = errors_.total() == errors_before;
  }

  static StripKind kind_of(const ParsedStrip& s) {
    if (s.header.op != StripOp::Ext) return StripKind::Copy;
    return s.is(ExtKind::Key) ? StripKind::Key : StripKind::Depth;
  }

  // A COPY, KEY or DEPTH strip: clipped to its display, then continuing the run at its column
  // or opening one.
  void route_strip(const ParsedStrip& s, const std::uint8_t* row, int y) {
    const StripHeader& h = s.header;
    const int x = s.header_x();
    const Target& t = targets_[h.display];
    if (t.index < 0) {
      ++errors_.missing_display;
      return unrepeatable(x);
    }
    if (s.length == 0) {  // a header in the last two pixels
      remember_header(y, x, raw_header(row, x));
      return unrepeatable(x);
    }
    if (h.x >= t.width || h.y >= t.height) {
      ++errors_.clips;
      return unrepeatable(x);
    }
    int length = s.length;
    const bool clipped = h.x + length > t.width;
    if (clipped) {
      ++errors_.clips;
      length = t.width - h.x;
    }
    ++routed_;
    fed_ |= std::uint64_t{1} << h.display;
    const StripKind kind = kind_of(s);
    const std::uint64_t ext = kind == StripKind::Copy ? 0 : raw_header(row, x + kHeaderPixels);
    if (kind != StripKind::Copy) out_.composited |= std::uint64_t{1} << h.display;
    const int list = t.band_offset + (h.y >> t.band_shift);
    const int last_y = std::min(t.height, ((h.y >> t.band_shift) + 1) << t.band_shift) - 1;
    const std::uint64_t next = clipped || h.y == last_y ? kNever : one_row_down(raw_header(row, x));
    sc_.seeing.push_back(
        {x, next, list, extend_run(s, list, length, y, kind, ext), h.y + 1, last_y, ext, kind});
  }

  // A header the fast path must not take for a repeat: the next scanline gets parsed.
  void unrepeatable(int x) { sc_.seeing.push_back({x, kNever, -1, 0, 0, 0}); }

  // Strips come left to right, as they did on the last scanline: walk its headers along. A
  // strip continues the run at its column if it is that run's next row; returns the run.
  std::uint32_t extend_run(const ParsedStrip& s, int list, int length, int y, StripKind kind,
                           std::uint64_t ext) {
    const int x = s.header_x();
    const std::vector<SeenHeader>& seen = sc_.seen;
    while (next_seen_ < seen.size() && seen[next_seen_].x < x) ++next_seen_;
    std::vector<Run>& runs = out_.bands[list];
    if (next_seen_ < seen.size() && seen[next_seen_].x == x && seen[next_seen_].list == list) {
      Run& r = runs[seen[next_seen_].run];
      if (r.dst_x == s.header.x && r.length == length && r.dst_y + r.rows == s.header.y &&
          r.kind == kind && r.ext == ext) {
        ++r.rows;
        return seen[next_seen_].run;
      }
    }
    runs.push_back({offset(y, s.source_x), s.source_x, y - s.header.y, s.header.x, s.header.y,
                    static_cast<std::uint16_t>(length), 1, kind,
                    static_cast<std::uint16_t>(s.header.width), s.extension.key, ext,
                    message_of(raw_header(f_.row(y), x))});
    return static_cast<std::uint32_t>(runs.size() - 1);
  }

  // Headers sit where tiles start, and tiles span many scanlines: the headers of a scanline
  // predict those a few scanlines below. Fetching those early turns one memory latency per
  // header into overlapped requests. They are fetched into every cache level because write()
  // reads the same lines again: a strip starts right after its header.
  void prefetch_headers(int y) const {
    if (y >= f_.height) return;
    const std::uint8_t* row = f_.row(y);
    pixel_copy::prefetch_line(row);
    const std::size_t n = std::min<std::size_t>(sc_.seen.size(), kTracked);
    for (std::size_t k = 0; k < n; ++k) {
      pixel_copy::prefetch_line(row + sc_.seen[k].x * f_.bytes_per_pixel);
    }
  }

  // Writing a band run by run keeps scan order on every display row if runs are ordered by
  // source row lag, then source column: two runs meet on a display row at source rows that
  // differ by their lags, the same on every row they share. Runs of packed tiles mostly come in
  // that order already.
  void order_runs() {
    const auto before = [](const Run& a, const Run& b) {
      return a.row_lag < b.row_lag || (a.row_lag == b.row_lag && a.src_x < b.src_x);
    };
    for (auto& runs : out_.bands) {
      if (!std::is_sorted(runs.begin(), runs.end(), before)) {
        std::sort(runs.begin(), runs.end(), before);
      }
    }
  }

  std::int64_t offset(int y, int x) const {
    return std::int64_t{f_.stride} * y + std::int64_t{x} * f_.bytes_per_pixel;
  }
  static std::uint64_t message_of(std::uint64_t raw) { return raw >> 3 & ~kMessageFrameBit; }
  void remember_header(int y, int x, std::uint64_t raw) {
    out_.others.push_back({offset(y, x), message_of(raw)});
  }
  void remember_end(int y, int x) {
    out_.others.push_back({offset(y, x), RememberedHeader::kAnyEnd});
  }

  void store_stats(int input) {
    InputFrameStats& st = out_.stats;
    st = InputFrameStats{};
    st.input = input;
    st.present = true;
    st.copy_strips = found_[static_cast<int>(StripKind::Copy)];
    st.key_strips = found_[static_cast<int>(StripKind::Key)];
    st.depth_strips = found_[static_cast<int>(StripKind::Depth)];
    st.skip_strips = skips_;
    st.routed_strips = routed_;
    st.parities = parities_;
    st.displays_fed = fed_;
    st.errors = errors_;
  }

  Layout& out_;
  ScanScratch& sc_;
  const std::vector<Target>& targets_;
  const InputFrame& f_;
  // Counted here, stored once at the end.
  StripErrorCounts errors_;
  std::uint64_t found_[3] = {};  // COPY, KEY and DEPTH strips, by StripKind
  std::uint64_t skips_ = 0, routed_ = 0, fed_ = 0;
  std::uint8_t parities_ = 0;
  bool repeatable_ = false;  // the last scanline was parsed without error
  std::size_t next_seen_ = 0;
};

}  // namespace

void parse_frame(const InputFrame& frame, int input, const std::vector<Target>& targets,
                 Layout& out, ScanScratch& scratch) {
  Scanner(frame, targets, out, scratch).scan(input);
}

}  // namespace l2::router_detail
