#include "video_player.h"

#include <algorithm>

#include <opencv2/imgproc.hpp>

namespace armmimic::gui {

QImage ImageFromMat(const cv::Mat& mat) {
  if (mat.empty()) return {};
  if (mat.type() == CV_8UC1) {
    return QImage(mat.data, mat.cols, mat.rows, static_cast<int>(mat.step),
                  QImage::Format_Grayscale8)
        .copy();
  }
  cv::Mat bgr = mat;
  if (mat.type() != CV_8UC3) mat.convertTo(bgr, CV_8UC3);
  return QImage(bgr.data, bgr.cols, bgr.rows, static_cast<int>(bgr.step), QImage::Format_BGR888)
      .copy();
}

QString DescribeSource(const VideoInfo& info) {
  if (info.kind != SourceKind::kCamera && info.codec.empty()) {  // still images: no frame rate
    return QString("%1: %2 images, %3×%4")
        .arg(QString::fromStdString(info.path))
        .arg(info.frame_count)
        .arg(info.size.width)
        .arg(info.size.height);
  }
  const QString what = info.kind == SourceKind::kCamera ? QStringLiteral("camera")
                       : info.codec.empty()             ? QStringLiteral("images")
                                                        : QString::fromStdString(info.codec);
  return QString("%1: %2 frames, %3 fps, %4×%5 (%6)")
      .arg(QString::fromStdString(info.path))
      .arg(info.frame_count)
      .arg(info.fps)
      .arg(info.size.width)
      .arg(info.size.height)
      .arg(what);
}

void FrameDecoder::open(const QStringList& inputs, int generation) {
  std::vector<std::string> list;
  for (const QString& s : inputs) list.push_back(s.toStdString());
  Status st;
  std::unique_ptr<VideoSource> fresh = VideoSource::Open(list, &st);
  if (!fresh) {  // what was open stays open
    emit openFailed(QString::fromStdString(st.message()), generation);
    return;
  }
  source_ = std::move(fresh);
  next_index_ = 0;
  emit opened(source_->info(), generation);
}

void FrameDecoder::close() { source_.reset(); }

void FrameDecoder::decode(int index, int generation) {
  if (!source_) return;
  const bool live = source_->info().kind == SourceKind::kCamera;
  if (!live && index != latest_request.load()) return;  // a newer request supersedes this one
  Status st;
  if (!live && index != next_index_) {
    st = source_->Seek(index);
    if (!st) {
      emit failed(QString::fromStdString(st.message()), generation);
      return;
    }
  }
  Frame frame;
  if (!source_->Read(&frame, &st)) {
    emit failed(st.ok() ? QString("%1: no frame %2")
                              .arg(QString::fromStdString(source_->info().path))
                              .arg(index)
                        : QString::fromStdString(st.message()),
                generation);
    return;
  }
  next_index_ = frame.index + 1;
  emit decoded(frame.index, ImageFromMat(frame.image), frame.time_s, generation);
}

VideoPlayer::VideoPlayer(QObject* parent) : QObject(parent), decoder_(new FrameDecoder) {
  qRegisterMetaType<armmimic::VideoInfo>();
  decoder_->moveToThread(&thread_);
  connect(&thread_, &QThread::finished, decoder_, &QObject::deleteLater);
  connect(decoder_, &FrameDecoder::opened, this, [this](const VideoInfo& info, int gen) {
    if (gen != generation_) return;
    info_ = info;
    open_ = true;
    current_ = 0;
    emit opened(info);
    if (isLive()) {
      play();
    } else {
      request(0);
    }
  });
  connect(decoder_, &FrameDecoder::openFailed, this, [this](const QString& msg, int gen) {
    if (gen != generation_) return;
    // A failed open leaves the previous input open, as it was.
    inputs_ = previous_inputs_;
    info_ = previous_info_;
    open_ = previous_open_;
    emit error(msg);
  });
  connect(decoder_, &FrameDecoder::decoded, this, &VideoPlayer::onDecoded);
  connect(decoder_, &FrameDecoder::failed, this, [this](const QString& msg, int gen) {
    if (gen != generation_) return;
    waiting_ = false;
    pause();
    emit error(msg);
  });
  connect(&timer_, &QTimer::timeout, this, &VideoPlayer::tick);
  thread_.setObjectName("armmimic-decoder");
  thread_.start();
}

VideoPlayer::~VideoPlayer() {
  thread_.quit();
  thread_.wait();
}

void VideoPlayer::open(const QStringList& inputs) {
  pause();
  previous_inputs_ = inputs_;
  previous_info_ = info_;
  previous_open_ = open_;
  ++generation_;
  open_ = false;
  inputs_ = inputs;
  info_ = VideoInfo();
  waiting_ = false;
  pending_ = -1;
  const int gen = generation_;
  QMetaObject::invokeMethod(decoder_, [d = decoder_, inputs, gen] { d->open(inputs, gen); });
}

void VideoPlayer::close() {
  pause();
  ++generation_;
  open_ = false;
  info_ = VideoInfo();
  image_ = QImage();
  QMetaObject::invokeMethod(decoder_, [d = decoder_] { d->close(); });
  emit closed();
}

void VideoPlayer::request(int index) {
  if (!open_) return;
  pending_ = index;
  waiting_ = true;
  decoder_->latest_request.store(index);
  const int gen = generation_;
  QMetaObject::invokeMethod(decoder_, [d = decoder_, index, gen] { d->decode(index, gen); });
}

void VideoPlayer::onDecoded(int index, const QImage& image, double time_s, int generation) {
  if (generation != generation_) return;
  if (!isLive() && index != pending_) return;
  waiting_ = false;
  current_ = index;
  image_ = image;
  emit frameShown(index, image, time_s);
}

void VideoPlayer::tick() {
  if (!open_ || waiting_) return;  // drop a tick rather than queue frames up
  if (isLive()) {
    request(current_ + 1);
    return;
  }
  if (current_ + 1 >= info_.frame_count) {
    pause();
    return;
  }
  request(current_ + 1);
}

void VideoPlayer::play() {
  if (!open_ || timer_.isActive()) return;
  if (!isLive() && current_ + 1 >= info_.frame_count) seek(0);
  const double fps = info_.fps > 0 ? info_.fps : 25.0;
  timer_.start(std::max(1, static_cast<int>(1000.0 / (fps * speed_))));
  emit playingChanged(true);
}

void VideoPlayer::pause() {
  if (!timer_.isActive()) return;
  timer_.stop();
  emit playingChanged(false);
}

void VideoPlayer::togglePlay() { isPlaying() ? pause() : play(); }

void VideoPlayer::seek(int index) {
  if (!open_ || isLive()) return;
  index = std::clamp(index, 0, std::max(0, info_.frame_count - 1));
  request(index);
}

void VideoPlayer::step(int delta) {
  pause();
  seek((waiting_ ? pending_ : current_) + delta);
}

void VideoPlayer::first() {
  pause();
  seek(0);
}

void VideoPlayer::last() {
  pause();
  seek(info_.frame_count - 1);
}

void VideoPlayer::setSpeed(double speed) {
  speed_ = std::clamp(speed, 0.05, 16.0);
  if (timer_.isActive()) {
    const double fps = info_.fps > 0 ? info_.fps : 25.0;
    timer_.setInterval(std::max(1, static_cast<int>(1000.0 / (fps * speed_))));
  }
}

}  // namespace armmimic::gui
