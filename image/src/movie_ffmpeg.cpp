// Movies through FFmpeg's libraries: the file's best video stream decoded in order and each
// frame converted to 8-bit RGB by swscale (point sampling: no size change, so no filtering).
extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/imgutils.h>
#include <libswscale/swscale.h>
}

#include <exception>
#include <memory>
#include <string>

#include "media_oiio.hpp"

namespace l2::png_codec {

namespace {

std::string av_error(int code) {
  char text[AV_ERROR_MAX_STRING_SIZE] = {};
  av_strerror(code, text, sizeof text);
  return text;
}

struct FormatCloser {
  void operator()(AVFormatContext* f) const { avformat_close_input(&f); }
};
struct CodecFreer {
  void operator()(AVCodecContext* c) const { avcodec_free_context(&c); }
};
struct PacketFreer {
  void operator()(AVPacket* p) const { av_packet_free(&p); }
};
struct FrameFreer {
  void operator()(AVFrame* f) const { av_frame_free(&f); }
};
struct ScaleFreer {
  void operator()(SwsContext* s) const { sws_freeContext(s); }
};

class FfmpegMovie final : public MovieDecoder {
 public:
  FfmpegMovie(std::unique_ptr<AVFormatContext, FormatCloser> format,
              std::unique_ptr<AVCodecContext, CodecFreer> codec, int stream)
      : format_(std::move(format)),
        codec_(std::move(codec)),
        stream_(stream),
        packet_(av_packet_alloc()),
        frame_(av_frame_alloc()) {}

  int width() const override { return codec_->width; }
  int height() const override { return codec_->height; }
  double frames_per_second() const override {
    const AVRational rate = av_guess_frame_rate(format_.get(), format_->streams[stream_], nullptr);
    return rate.num > 0 && rate.den > 0 ? av_q2d(rate) : 0.0;
  }

  Result<bool> next_frame(std::uint8_t* rgb) override {
    if (!packet_ || !frame_) return Failure{"cannot decode: out of memory"};
    for (;;) {
      const int received = avcodec_receive_frame(codec_.get(), frame_.get());
      if (received == 0) {
        if (Status converted = convert(rgb); !converted.ok()) return Failure{converted.reason()};
        return true;
      }
      if (received == AVERROR_EOF) return false;
      if (received != AVERROR(EAGAIN)) return Failure{"cannot decode frame: " + av_error(received)};
      if (Status fed = feed(); !fed.ok()) return Failure{fed.reason()};
    }
  }

 private:
  // One packet of the video stream into the decoder, or the end of the file (draining it).
  Status feed() {
    for (;;) {
      const int read = av_read_frame(format_.get(), packet_.get());
      if (read == AVERROR_EOF) {
        avcodec_send_packet(codec_.get(), nullptr);
        return {};
      }
      if (read < 0) return Failure{"cannot read: " + av_error(read)};
      const bool ours = packet_->stream_index == stream_;
      const int sent = ours ? avcodec_send_packet(codec_.get(), packet_.get()) : 0;
      av_packet_unref(packet_.get());
      if (sent < 0) return Failure{"cannot decode: " + av_error(sent)};
      if (ours) return {};
    }
  }

  Status convert(std::uint8_t* rgb) {
    const int w = codec_->width, h = codec_->height;
    if (frame_->width != w || frame_->height != h) {
      return Failure{"cannot decode: a frame of " + std::to_string(frame_->width) + "x" +
                     std::to_string(frame_->height) + " in a " + std::to_string(w) + "x" +
                     std::to_string(h) + " movie"};
    }
    scale_.reset(sws_getCachedContext(scale_.release(), w, h,
                                      static_cast<AVPixelFormat>(frame_->format), w, h,
                                      AV_PIX_FMT_RGB24, SWS_POINT, nullptr, nullptr, nullptr));
    if (!scale_) return Failure{"cannot convert its pixel format to RGB"};
    std::uint8_t* planes[1] = {rgb};
    const int strides[1] = {3 * w};
    sws_scale(scale_.get(), frame_->data, frame_->linesize, 0, h, planes, strides);
    av_frame_unref(frame_.get());
    return {};
  }

  std::unique_ptr<AVFormatContext, FormatCloser> format_;
  std::unique_ptr<AVCodecContext, CodecFreer> codec_;
  int stream_;
  std::unique_ptr<AVPacket, PacketFreer> packet_;
  std::unique_ptr<AVFrame, FrameFreer> frame_;
  std::unique_ptr<SwsContext, ScaleFreer> scale_;
};

}  // namespace

Result<std::unique_ptr<MovieDecoder>> open_movie(const char* path) try {
  av_log_set_level(AV_LOG_QUIET);  // reasons come back in one line; FFmpeg prints nothing
  AVFormatContext* opened = nullptr;
  if (const int r = avformat_open_input(&opened, path, nullptr, nullptr); r < 0) {
    // A container that ends before any stream's first packet: a movie of no frames.
    if (r == AVERROR_EOF) return Failure{"holds no video frames"};
    return Failure{"cannot read as a movie: " + av_error(r)};
  }
  std::unique_ptr<AVFormatContext, FormatCloser> format(opened);
  if (const int r = avformat_find_stream_info(format.get(), nullptr); r < 0) {
    if (r == AVERROR_EOF) return Failure{"holds no video frames"};
    return Failure{"cannot read as a movie: " + av_error(r)};
  }
  const AVCodec* decoder = nullptr;
  const int stream = av_find_best_stream(format.get(), AVMEDIA_TYPE_VIDEO, -1, -1, &decoder, 0);
  if (stream == AVERROR_STREAM_NOT_FOUND) return Failure{"holds no video stream"};
  if (stream < 0 || !decoder) {
    return Failure{"no decoder for its video stream: " + av_error(stream)};
  }
  std::unique_ptr<AVCodecContext, CodecFreer> codec(avcodec_alloc_context3(decoder));
  if (!codec) return Failure{"cannot decode: out of memory"};
  avcodec_parameters_to_context(codec.get(), format->streams[stream]->codecpar);
  if (const int r = avcodec_open2(codec.get(), decoder, nullptr); r < 0) {
    return Failure{"cannot open its video decoder: " + av_error(r)};
  }
  if (codec->width <= 0 || codec->height <= 0) {
    return Failure{"its video stream has no frame size"};
  }
  return std::unique_ptr<MovieDecoder>(
      new FfmpegMovie(std::move(format), std::move(codec), stream));
} catch (const std::exception& e) {
  return Failure{std::string("cannot read as a movie: ") + e.what()};
}

}  // namespace l2::png_codec
