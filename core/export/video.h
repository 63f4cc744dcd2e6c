#pragma once
/// Frames encoded as a video (MP4, WebM) or an animated GIF by FFmpeg's
/// `ffmpeg` program, fed raw RGBA frames through a pipe.
///
/// The program is looked up as SNAXELS_FFMPEG names it, else as `ffmpeg` on
/// the PATH. MP4 is H.264 in yuv420p (what every player reads), which needs
/// an even width and height: an odd canvas is padded by a pixel of white on
/// the right or bottom. WebM is VP9. A GIF's frame delays are whole
/// hundredths of a second: at a rate that is 100 over a whole number (25,
/// 20, 50 fps) every delay is exact; at another (24 fps) FFmpeg mixes the
/// two nearest delays (4 and 5 hundredths) so the clip keeps its length.

#include <memory>
#include <string>

#include "snaxels/export/output_file.h"
#include "snaxels/export/raster.h"

namespace snaxels {

/// The ffmpeg program that would be run, or an Error saying it is missing
/// (checked before an export starts).
std::string require_ffmpeg();

/// The quality an MP4 or WebM is encoded at: FFmpeg's constant rate factor,
/// lower is better and bigger (0 to 51 for MP4, 0 to 63 for WebM); these
/// are the defaults, visually lossless for line art.
inline constexpr int kDefaultMp4Crf = 18;
inline constexpr int kDefaultWebmCrf = 30;

class VideoEncoder {
  public:
    /// Starts ffmpeg writing @p kind (Mp4, Webm or Gif) of @p width x
    /// @p height frames at @p fps to a temporary beside @p path, at quality
    /// @p crf (MP4 and WebM; -1: the format's default; a GIF has none).
    VideoEncoder(const std::string& path, OutputKind kind, int width, int height, double fps, int crf = -1);
    /// Unless finished: stops ffmpeg and removes its file.
    ~VideoEncoder();
    VideoEncoder(const VideoEncoder&) = delete;
    VideoEncoder& operator=(const VideoEncoder&) = delete;

    /// The next frame (its size the one given; the background is white
    /// where it is transparent).
    void add(const RgbaImage& frame);
    /// Ends the stream, waits for ffmpeg and puts the file in place; throws
    /// snaxels::Error with ffmpeg's last message if it failed.
    void finish();

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace snaxels
