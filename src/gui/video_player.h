// VideoPlayer: opens a video, image folder or camera and delivers frames for display. Decoding
// runs on its own thread (FrameDecoder); only the newest request is served, so scrubbing stays
// smooth. Playback speed, stepping and seeking live here, not in the widgets.
#pragma once

#include <atomic>
#include <memory>

#include <QImage>
#include <QObject>
#include <QStringList>
#include <QThread>
#include <QTimer>

#include "armmimic/core/video_source.h"

namespace armmimic::gui {

QImage ImageFromMat(const cv::Mat& bgr);  // deep copy of a CV_8UC3 BGR or CV_8UC1 image
// "scene.avi: 300 frames, 30 fps, 320×240 (MJPG)"; "views: 48 images, 320×240"
QString DescribeSource(const VideoInfo& info);

// Lives on the decoder thread.
class FrameDecoder : public QObject {
  Q_OBJECT
 public:
  std::atomic<int> latest_request{-1};

 public slots:
  void open(const QStringList& inputs, int generation);
  void decode(int index, int generation);
  void close();

 signals:
  void opened(const armmimic::VideoInfo& info, int generation);
  void openFailed(const QString& message, int generation);
  void decoded(int index, const QImage& image, double time_s, int generation);
  void failed(const QString& message, int generation);

 private:
  std::unique_ptr<VideoSource> source_;
  int next_index_ = 0;  // what Read() returns next without a seek
};

class VideoPlayer : public QObject {
  Q_OBJECT
 public:
  explicit VideoPlayer(QObject* parent = nullptr);
  ~VideoPlayer() override;

  // Opens asynchronously; emits opened() or error(). On error what was open stays open.
  void open(const QStringList& inputs);
  void close();
  bool isOpen() const { return open_; }
  bool isLive() const { return open_ && info_.kind == SourceKind::kCamera; }
  const VideoInfo& info() const { return info_; }
  const QStringList& inputs() const { return inputs_; }
  int frameCount() const { return info_.frame_count; }
  int currentFrame() const { return current_; }
  bool isPlaying() const { return timer_.isActive(); }
  double speed() const { return speed_; }
  const QImage& currentImage() const { return image_; }

 public slots:
  void play();
  void pause();
  void togglePlay();
  void seek(int index);
  void step(int delta);
  void first();
  void last();
  void setSpeed(double speed);

 signals:
  void opened(const armmimic::VideoInfo& info);
  void closed();
  void frameShown(int index, const QImage& image, double time_s);
  void playingChanged(bool playing);
  void error(const QString& message);

 private:
  void request(int index);
  void onDecoded(int index, const QImage& image, double time_s, int generation);
  void tick();

  QThread thread_;
  FrameDecoder* decoder_;
  QTimer timer_;
  QStringList inputs_;
  VideoInfo info_;
  bool open_ = false;
  int generation_ = 0;
  int current_ = 0;
  int pending_ = -1;  // frame requested and not yet shown
  bool waiting_ = false;
  double speed_ = 1.0;
  QImage image_;
  QStringList previous_inputs_;  // restored when an open fails
  VideoInfo previous_info_;
  bool previous_open_ = false;
};

}  // namespace armmimic::gui

Q_DECLARE_METATYPE(armmimic::VideoInfo)
