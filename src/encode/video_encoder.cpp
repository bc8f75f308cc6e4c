#include "encode/video_encoder.h"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/imgutils.h>
#include <libavutil/opt.h>
#include <libavutil/pixdesc.h>
}

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>

#include "core/error.h"
#include "io/output_ledger.h"
#include "encode/yuv_converter.h"

namespace cablefilm {
namespace {

std::string AvError(int code) {
  char buf[AV_ERROR_MAX_STRING_SIZE] = {0};
  av_strerror(code, buf, sizeof buf);
  return buf;
}

}  // namespace

struct VideoEncoder::Impl {
  std::string path, temp_path;
  VideoOptions options;
  AVFormatContext* format = nullptr;
  AVCodecContext* codec = nullptr;
  AVStream* stream = nullptr;
  AVFrame* frame = nullptr;
  AVPacket* packet = nullptr;
  std::unique_ptr<YuvConverter> yuv;
  long frames = 0;
  bool header_written = false;
  bool finished = false;

  void Fail(const std::string& what, int code) {
    throw Error("video " + path + ": " + what + (code ? ": " + AvError(code) : std::string()));
  }

  // Receives every packet the encoder has ready and hands it to the muxer (mux.c's loop).
  void Drain() {
    for (;;) {
      int ret = avcodec_receive_packet(codec, packet);
      if (ret == AVERROR(EAGAIN) || ret == AVERROR_EOF) return;
      if (ret < 0) Fail("encoding failed", ret);
      av_packet_rescale_ts(packet, codec->time_base, stream->time_base);
      packet->stream_index = stream->index;
      ret = av_interleaved_write_frame(format, packet);  // takes ownership of the packet's data
      if (ret < 0) Fail("writing a packet failed (disk full?)", ret);
    }
  }

  void Release() {
    yuv.reset();
    av_frame_free(&frame);
    av_packet_free(&packet);
    avcodec_free_context(&codec);
    if (format) {
      if (format->pb) avio_closep(&format->pb);
      avformat_free_context(format);
      format = nullptr;
    }
  }
};

VideoEncoder::VideoEncoder(const std::string& path, const VideoOptions& options)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.path = path;
  m.options = options;
  m.temp_path = PartialPath(path);
  RecordOutput(path);  // and the film being made, then its remuxed copy (Finish)
  RecordOutput(m.temp_path);
  RecordOutput(path + ".tmp.mp4");
  if (options.width <= 0 || options.height <= 0 || options.width % 2 || options.height % 2)
    throw Error("video " + path + ": width and height must be positive and even, got " +
                std::to_string(options.width) + "x" + std::to_string(options.height));
  if (!(options.fps > 0) || !std::isfinite(options.fps))
    throw Error("video " + path + ": frame rate must be positive, got " + std::to_string(options.fps));
  try {
    av_log_set_level(AV_LOG_ERROR);
    int ret = avformat_alloc_output_context2(&m.format, nullptr, "mp4", m.temp_path.c_str());
    if (ret < 0 || !m.format) m.Fail("cannot create an MP4 muxer", ret);
    const AVCodec* encoder = avcodec_find_encoder_by_name(options.codec.c_str());
    if (!encoder) m.Fail("encoder '" + options.codec + "' not available in this libavcodec", 0);
    m.stream = avformat_new_stream(m.format, nullptr);
    if (!m.stream) m.Fail("cannot add a stream", 0);
    m.codec = avcodec_alloc_context3(encoder);
    if (!m.codec) m.Fail("cannot allocate the encoder", 0);
    AVCodecContext* c = m.codec;
    c->width = options.width;
    c->height = options.height;
    c->framerate = av_d2q(options.fps, 100000);
    c->time_base = av_inv_q(c->framerate);
    c->pix_fmt = AV_PIX_FMT_YUV420P;
    c->gop_size = std::max(1, static_cast<int>(std::lround(options.fps * 2)));  // a key frame every 2 s
    c->thread_count = options.threads;
    c->color_primaries = AVCOL_PRI_BT709;
    c->color_trc = AVCOL_TRC_IEC61966_2_1;  // the frames are sRGB
    c->colorspace = AVCOL_SPC_BT709;
    c->color_range = AVCOL_RANGE_MPEG;
    if (m.format->oformat->flags & AVFMT_GLOBALHEADER) c->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
    AVDictionary* codec_options = nullptr;
    av_dict_set(&codec_options, "preset", options.preset.c_str(), 0);
    av_dict_set(&codec_options, "crf", std::to_string(options.crf).c_str(), 0);
    ret = avcodec_open2(c, encoder, &codec_options);
    const bool unused = av_dict_count(codec_options) > 0;
    av_dict_free(&codec_options);
    if (ret < 0)
      m.Fail("cannot open encoder " + options.codec + " (preset " + options.preset + ", crf " +
                 std::to_string(options.crf) + ")",
             ret);
    if (unused) m.Fail("encoder " + options.codec + " does not take preset/crf options", 0);
    ret = avcodec_parameters_from_context(m.stream->codecpar, c);
    if (ret < 0) m.Fail("cannot copy the stream parameters", ret);
    m.stream->time_base = c->time_base;
    m.stream->avg_frame_rate = c->framerate;

    m.frame = av_frame_alloc();
    m.packet = av_packet_alloc();
    if (!m.frame || !m.packet) m.Fail("out of memory", 0);
    m.frame->format = c->pix_fmt;
    m.frame->width = c->width;
    m.frame->height = c->height;
    ret = av_frame_get_buffer(m.frame, 0);
    if (ret < 0) m.Fail("cannot allocate a frame", ret);

    m.yuv = std::make_unique<YuvConverter>(c->width, c->height);

    ret = avio_open(&m.format->pb, m.temp_path.c_str(), AVIO_FLAG_WRITE);
    if (ret < 0) m.Fail("cannot create " + m.temp_path, ret);
    AVDictionary* format_options = nullptr;
    // Fragmented, a fragment per frame: whatever stops the program (even SIGKILL), the partial
    // film plays up to its last frame. Finish() remuxes it into an ordinary film.
    av_dict_set(&format_options, "movflags", "+frag_every_frame+empty_moov+default_base_moof", 0);
    av_dict_set(&format_options, "flush_packets", "1", 0);
    ret = avformat_write_header(m.format, &format_options);
    av_dict_free(&format_options);
    if (ret < 0) m.Fail("cannot write the MP4 header", ret);
    m.header_written = true;
  } catch (...) {
    m.Release();
    std::remove(m.temp_path.c_str());
    throw;
  }
}

VideoEncoder::~VideoEncoder() {
  if (!impl_) return;
  if (!impl_->finished) {
    impl_->Release();
    std::remove(impl_->temp_path.c_str());
  }
}

const std::string& VideoEncoder::partial_path() const { return impl_->temp_path; }

void VideoEncoder::AddFrame(const Image& image, const std::vector<ImageRect>* changed) {
  Impl& m = *impl_;
  if (m.finished) throw Error("video " + m.path + ": frame added after Finish()");
  if (image.width != m.codec->width || image.height != m.codec->height)
    throw Error("video " + m.path + ": frame is " + std::to_string(image.width) + "x" +
                std::to_string(image.height) + ", film is " + std::to_string(m.codec->width) +
                "x" + std::to_string(m.codec->height));
  // The encoder may still hold a reference to the previous frame's buffers (then new ones
  // are made with a copy of their bytes: they still hold the previous frame).
  int ret = av_frame_make_writable(m.frame);
  if (ret < 0) m.Fail("cannot make the frame writable", ret);
  m.yuv->Convert(image, m.frame->data, m.frame->linesize, m.frames > 0 ? changed : nullptr);
  m.frame->pts = m.frames;
  ret = avcodec_send_frame(m.codec, m.frame);
  if (ret < 0) m.Fail("cannot send frame " + std::to_string(m.frames), ret);
  ++m.frames;
  m.Drain();
}

// Copies the packets of `in` into an MP4 at `out` with its index first (+faststart), so that
// the finished film streams and every player knows its duration. No re-encoding.
static void Remux(const std::string& in, const std::string& out) {
  AVFormatContext* src = nullptr;
  AVFormatContext* dst = nullptr;
  AVPacket* packet = av_packet_alloc();
  auto fail = [&](const std::string& what, int code) {
    av_packet_free(&packet);
    avformat_close_input(&src);
    if (dst) {
      if (dst->pb) avio_closep(&dst->pb);
      avformat_free_context(dst);
    }
    std::remove(out.c_str());
    throw Error("video " + out + ": " + what + (code ? ": " + AvError(code) : std::string()));
  };
  if (!packet) fail("out of memory", 0);
  int ret = avformat_open_input(&src, in.c_str(), nullptr, nullptr);
  if (ret < 0) fail("cannot reopen " + in, ret);
  ret = avformat_find_stream_info(src, nullptr);
  if (ret < 0) fail("cannot read " + in, ret);
  ret = avformat_alloc_output_context2(&dst, nullptr, "mp4", out.c_str());
  if (ret < 0 || !dst) fail("cannot create an MP4 muxer", ret);
  for (unsigned i = 0; i < src->nb_streams; ++i) {
    AVStream* s = avformat_new_stream(dst, nullptr);
    if (!s) fail("cannot add a stream", 0);
    ret = avcodec_parameters_copy(s->codecpar, src->streams[i]->codecpar);
    if (ret < 0) fail("cannot copy the stream parameters", ret);
    s->codecpar->codec_tag = 0;
    s->time_base = src->streams[i]->time_base;
    s->avg_frame_rate = src->streams[i]->avg_frame_rate;
  }
  ret = avio_open(&dst->pb, out.c_str(), AVIO_FLAG_WRITE);
  if (ret < 0) fail("cannot create the file", ret);
  AVDictionary* options = nullptr;
  av_dict_set(&options, "movflags", "+faststart", 0);
  ret = avformat_write_header(dst, &options);
  av_dict_free(&options);
  if (ret < 0) fail("cannot write the MP4 header", ret);
  while ((ret = av_read_frame(src, packet)) >= 0) {
    AVStream* from = src->streams[packet->stream_index];
    AVStream* to = dst->streams[packet->stream_index];
    av_packet_rescale_ts(packet, from->time_base, to->time_base);
    packet->pos = -1;
    ret = av_interleaved_write_frame(dst, packet);
    if (ret < 0) fail("writing a packet failed (disk full?)", ret);
  }
  if (ret != AVERROR_EOF) fail("cannot read " + in, ret);
  ret = av_write_trailer(dst);  // with +faststart, moves the moov atom to the front
  if (ret < 0) fail("cannot write the MP4 trailer", ret);
  ret = avio_closep(&dst->pb);
  if (ret < 0) fail("cannot close the file", ret);
  avformat_free_context(dst);
  avformat_close_input(&src);
  av_packet_free(&packet);
}

std::string PartialPath(const std::string& path) {
  const std::string ext = ".mp4";
  if (path.size() > ext.size() && path.compare(path.size() - ext.size(), ext.size(), ext) == 0)
    return path.substr(0, path.size() - ext.size()) + ".partial.mp4";
  return path + ".partial.mp4";
}

void VideoEncoder::Close() {
  Impl& m = *impl_;
  int ret = avcodec_send_frame(m.codec, nullptr);  // enter draining mode
  if (ret < 0 && ret != AVERROR_EOF) m.Fail("cannot flush the encoder", ret);
  m.Drain();
  ret = av_write_trailer(m.format);
  if (ret < 0) m.Fail("cannot write the MP4 trailer", ret);
  ret = avio_closep(&m.format->pb);
  if (ret < 0) m.Fail("cannot close " + m.temp_path, ret);
  m.Release();
  m.finished = true;
}

void VideoEncoder::Finish() {
  Impl& m = *impl_;
  if (m.finished) return;
  Close();
  // The whole film: remuxed beside its final name, then renamed over it (whole or nothing).
  const std::string tmp = m.path + ".tmp.mp4";
  try {
    Remux(m.temp_path, tmp);
  } catch (...) {
    std::remove(m.temp_path.c_str());
    throw;
  }
  std::remove(m.temp_path.c_str());
  if (std::rename(tmp.c_str(), m.path.c_str()) != 0) {
    std::remove(tmp.c_str());
    throw Error("cannot rename " + tmp + " to " + m.path + ": " + std::strerror(errno));
  }
}

void VideoEncoder::FinishPartial() {
  Impl& m = *impl_;
  if (m.finished) return;
  Close();  // it stays under its .partial.mp4 name, and plays
}

long VideoEncoder::frames_added() const { return impl_->frames; }
const std::string& VideoEncoder::path() const { return impl_->path; }

namespace {

// Offsets of the top-level 'moov' and 'mdat' boxes of an MP4 file (ISO BMFF box walk).
void FindTopLevelBoxes(const std::string& path, long long* moov, long long* mdat) {
  std::ifstream in(path, std::ios::binary);
  long long offset = 0;
  unsigned char header[16];
  while (in.read(reinterpret_cast<char*>(header), 8)) {
    unsigned long long size = (static_cast<unsigned long long>(header[0]) << 24) |
                              (header[1] << 16) | (header[2] << 8) | header[3];
    const std::string type(reinterpret_cast<char*>(header) + 4, 4);
    if (size == 1) {  // 64-bit size follows
      if (!in.read(reinterpret_cast<char*>(header + 8), 8)) break;
      size = 0;
      for (int i = 8; i < 16; ++i) size = (size << 8) | header[i];
    }
    if (type == "moov" && *moov < 0) *moov = offset;
    if (type == "mdat" && *mdat < 0) *mdat = offset;
    if (size < 8) break;  // size 0 = to end of file
    offset += static_cast<long long>(size);
    in.seekg(offset);
  }
}

}  // namespace

VideoInfo ProbeVideo(const std::string& path) {
  AVFormatContext* format = nullptr;
  int ret = avformat_open_input(&format, path.c_str(), nullptr, nullptr);
  if (ret < 0) throw Error("cannot open video " + path + ": " + AvError(ret));
  VideoInfo info;
  try {
    ret = avformat_find_stream_info(format, nullptr);
    if (ret < 0) throw Error("cannot read streams of " + path + ": " + AvError(ret));
    const int index = av_find_best_stream(format, AVMEDIA_TYPE_VIDEO, -1, -1, nullptr, 0);
    if (index < 0) throw Error("no video stream in " + path);
    const AVStream* st = format->streams[index];
    info.codec = avcodec_get_name(st->codecpar->codec_id);
    const char* pix = av_get_pix_fmt_name(static_cast<AVPixelFormat>(st->codecpar->format));
    info.pixel_format = pix ? pix : "";
    info.width = st->codecpar->width;
    info.height = st->codecpar->height;
    info.fps = st->avg_frame_rate.den ? av_q2d(st->avg_frame_rate) : 0;
    if (st->duration > 0)
      info.duration = static_cast<double>(st->duration) * av_q2d(st->time_base);
    else if (format->duration > 0)
      info.duration = static_cast<double>(format->duration) / AV_TIME_BASE;
    AVPacket* packet = av_packet_alloc();
    while (av_read_frame(format, packet) >= 0) {
      if (packet->stream_index == index) ++info.frames;
      av_packet_unref(packet);
    }
    av_packet_free(&packet);
  } catch (...) {
    avformat_close_input(&format);
    throw;
  }
  avformat_close_input(&format);
  FindTopLevelBoxes(path, &info.moov_offset, &info.mdat_offset);
  return info;
}

}  // namespace cablefilm
