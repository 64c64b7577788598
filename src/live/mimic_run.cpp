#include "armmimic/live/mimic_run.h"

#include <QMetaObject>

#include "armmimic/serial/serial_link.h"

namespace armmimic::live {

MimicRun::MimicRun(serial::SerialLink* link, QObject* parent)
    : QObject(parent), link_(link), dry_run_(link == nullptr) {}

MimicRun::~MimicRun() {
  cancel_.store(true);
  if (thread_.joinable()) thread_.join();
  if (link_ && !dry_run_ && started_) {
    // Nothing of this run may be called once it is gone: no signal, no protocol callback.
    disconnect(link_, nullptr, this, nullptr);
    if (!link_done_) link_->Cancel("the live run was closed");
    link_->protocol().SetGate(nullptr);
    link_->protocol().SetSentCallback(nullptr);
    link_->protocol().SetAckCallback(nullptr);
  }
  stream_.Close();
}

void MimicRun::SetDryWriter(std::function<void(const robot::LinkLine&)> writer) {
  dry_writer_ = std::move(writer);
}

void MimicRun::SetFrameHook(std::function<void(const Frame&, const ArmMeasurement&)> hook) {
  frame_hook_ = std::move(hook);
}

double MimicRun::Now() const { return Seconds(std::chrono::steady_clock::now()); }

double MimicRun::Seconds(std::chrono::steady_clock::time_point t) const {
  return std::chrono::duration<double>(t - epoch_).count();
}

Status MimicRun::Start(const MimicOptions& options) {
  if (started_) return Status::Error("the live run has already started");
  options_ = options;
  robot::LiveStreamOptions stream = options.stream;
  stream.sample_rate_hz = options.fallback_fps;
  // The pose engine's named arm (the person's own, seen facing the camera) gives the image side
  // the 3-D columns' azimuth is read from; with --side auto it is decided only once the video
  // runs, and the stream turns J1 from the 2-D columns.
  if (options.analysis.engine.kind == EngineKind::kPose) {
    const PoseSide side = options.analysis.engine.pose.side;
    stream.planner.mapping.image_side = side == PoseSide::kLeft    ? 1
                                        : side == PoseSide::kRight ? -1
                                                                   : 0;
  }
  Status st = options.analysis.Check();
  if (st && AnalysedArms(options.analysis).size() > 1) {
    st = Status::Error("pose.side", "the robot follows one arm: name it (left or right), not both");
  }
  if (st) st = stream_.Begin(stream);
  if (!st) return st;
  epoch_ = std::chrono::steady_clock::now();
  stream_.SetClock([this] { return Now(); });
  stream_.SetCommandCallback(
      [this](const robot::JointArray& target, int frame) { emit commandWritten(target, frame); });
  started_ = true;
  if (!dry_run_) {
    if (!link_) return Status::Error("the serial link is gone");
    stream_.Attach(&link_->protocol(), [this](const robot::LinkLine& l) {
      if (link_) link_->Append(l);
    });
    connect(link_, &serial::SerialLink::finished, this, &MimicRun::OnLinkFinished);
    // The port's owner deleting it mid-run ends the run as a lost link.
    connect(link_, &QObject::destroyed, this, [this] {
      if (!link_done_) {
        failure_ = failure_.empty() ? "the serial link was closed" : failure_;
        OnLinkGone();
      }
    });
    link_->StartStream("mimic");
  } else {
    link_done_ = true;  // a dry run has no link to wait for
    stream_.SetWriter(dry_writer_);
  }
  stream_.SendOpening();
  stream_begun_ = true;

  // The analysis thread: everything it hands over is posted to this object's thread.
  thread_ = std::thread([this] {
    AnalysisCallbacks cb;
    cb.cancel = &cancel_;
    cb.on_open = [this](const VideoInfo& info) {
      QMetaObject::invokeMethod(
          this, [this, info] { OnOpen(info); }, Qt::QueuedConnection);
    };
    double capture_s = 0;
    cb.on_frame = [this, &capture_s](const Frame&, std::chrono::steady_clock::time_point t) {
      capture_s = Seconds(t);
    };
    cb.on_measurement = [this, &capture_s](const Frame& frame, const ArmMeasurement& m) {
      const double analysed_s = Now();
      if (frame_hook_) frame_hook_(frame, m);
      if (!m.row()) return;
      const AngleRow row = m.ToRow();
      const double captured = capture_s;
      QMetaObject::invokeMethod(
          this, [this, row, captured, analysed_s] { OnRow(row, captured, analysed_s); },
          Qt::QueuedConnection);
    };
    AnalysisSummary summary;
    const Status s = AnalyzeToFile(options_.analysis, options_.angles_path, cb, &summary);
    QMetaObject::invokeMethod(
        this, [this, s, summary] { OnAnalysisDone(s, summary); }, Qt::QueuedConnection);
  });
  return Status::Ok();
}

void MimicRun::OnOpen(const VideoInfo& info) {
  if (!(info.fps > 0) || stream_.planner().stats().frames > 0) return;
  const Status s = stream_.SetSampleRate(info.fps);
  if (!s.ok()) Stop(info.path + ": " + s.message());
}

void MimicRun::OnRow(const AngleRow& row, double capture_s, double analysed_s) {
  if (finished_) return;
  const double now = Now();
  stream_.OnFrame(row, capture_s, analysed_s, now);
  const robot::StreamPlanner& p = stream_.planner();
  const robot::HoldReason hold = stream_.holding(now);
  emit framePlanned(
      row.frame, row.ok(), p.has_target(), p.target(),
      hold == robot::HoldReason::kNone ? QString() : QString(robot::HoldReasonName(hold)));
}

void MimicRun::SetHeld(bool held) { stream_.SetHeld(held, Now()); }

void MimicRun::Stop(const std::string& reason) {
  if (!started_ || finished_) return;
  ++stops_;
  if (failure_.empty()) failure_ = reason;
  stream_.Stop(reason);
  cancel_.store(true);
  if (link_ && !dry_run_ && !link_done_) {
    if (stops_ > 1) {
      link_->Cancel(reason);
    } else {
      link_->EndStream();  // finishes once the line in flight is acknowledged
    }
  }
  MaybeFinish();
}

void MimicRun::OnAnalysisDone(const Status& status, const AnalysisSummary& summary) {
  if (thread_.joinable()) thread_.join();
  analysis_done_ = true;
  summary_ = summary;
  if (!status && failure_.empty()) {
    failure_ = status.message();
    failure_key_ = status.key();
  }
  if (status && !summary.incomplete.empty() && failure_.empty()) {
    failure_ = summary.video.path + ": " + summary.incomplete;
  }
  if (status && !summary.cancelled && failure_.empty()) ended_normally_ = true;
  stream_.Stop(failure_);
  if (link_ && !dry_run_ && !link_done_) link_->EndStream();
  MaybeFinish();
}

void MimicRun::OnLinkGone() {
  link_done_ = true;
  ended_normally_ = false;
  stream_.Stop(failure_);
  cancel_.store(true);
  MaybeFinish();
}

void MimicRun::OnLinkFinished(bool ok) {
  if (link_done_ || !link_) return;
  link_done_ = true;
  if (!ok) {
    const std::string message = link_->protocol().error_message();
    if (failure_.empty() || link_->protocol().error() != robot::LinkError::kAborted ||
        stops_ == 0) {
      failure_ = message;
      failure_key_ = link_->protocol().error_key();
    }

    ended_normally_ = false;
    stream_.Stop(failure_);
    cancel_.store(true);
  }
  MaybeFinish();
}

void MimicRun::MaybeFinish() {
  if (finished_ || !analysis_done_ || !link_done_) return;
  finished_ = true;
  if (link_) disconnect(link_, nullptr, this, nullptr);
  const Status closed = stream_.Close();
  if (!closed && failure_.empty()) failure_ = closed.message();
  const bool ok = ended_normally_ && failure_.empty();
  emit finished(ok, QString::fromStdString(failure_));
}

}  // namespace armmimic::live
