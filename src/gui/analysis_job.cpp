#include "analysis_job.h"

#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFileInfo>

#include "armmimic/core/image_io.h"
#include "armmimic/core/output_file.h"
#include "video_player.h"

namespace armmimic::gui {

void AnalysisWorker::analyze(const AnalysisOptions& options, const QString& output_path,
                             bool live) {
  AnalysisCallbacks cb;
  cb.cancel = cancel_;
  cb.on_phase = [this](const std::string& text) { emit phase(QString::fromStdString(text)); };
  cb.on_progress = [this](int done, int total) { emit progress(done, total); };
  cb.on_estimate = [this](const std::string& text) {
    emit estimated(QString::fromStdString(text));
  };
  cb.on_measurement = [this, live](const Frame& frame, const ArmMeasurement& m) {
    if (live) emit liveFrame(frame.index, ImageFromMat(frame.image), frame.time_s);
    emit measured(m);
  };
  AnalysisSummary summary;
  const Status st = AnalyzeToFile(options, output_path.toStdString(), cb, &summary);
  emit analysisFinished(st ? QString() : QString::fromStdString(st.message()),
                        QString::fromStdString(st.key()), summary);
}

void AnalysisWorker::estimateBackground(const QStringList& inputs, int start, int count,
                                        const QString& output_path) {
  std::vector<std::string> list;
  for (const QString& s : inputs) list.push_back(s.toStdString());
  AnalysisCallbacks cb;
  cb.cancel = cancel_;
  cb.on_progress = [this](int done, int total) { emit progress(done, total); };
  cv::Mat background;
  Status st = EstimateBackground(list, start, count, &background, cb);
  if (st && cancel_->load()) st = Status::Error("background estimation cancelled");
  if (st) {
    std::vector<unsigned char> png;
    const std::string path = output_path.toStdString();
    std::string ext = QFileInfo(output_path).suffix().toLower().toStdString();
    if (ext.empty()) ext = "png";
    if (Status encoded = EncodeImage("." + ext, background, {}, &png); !encoded) {
      st = Status::Error(path + ": cannot encode the background (" + encoded.message() + ")");
    } else {
      st = WriteOutputFile(path, std::string(png.begin(), png.end()));
    }
  }
  emit backgroundFinished(st ? QString() : QString::fromStdString(st.message()), output_path);
}

void AnalysisWorker::estimateStandstill(const AnalysisOptions& options) {
  StandstillJoints joints;
  const Status st = EstimateStandstillJoints(options, &joints);
  emit standstillFinished(st ? QString() : QString::fromStdString(st.message()),
                          QString::fromStdString(st.key()), joints);
}

AnalysisJob::AnalysisJob(QObject* parent) : QObject(parent), worker_(new AnalysisWorker(&cancel_)) {
  qRegisterMetaType<armmimic::AnalysisOptions>();
  qRegisterMetaType<armmimic::ArmMeasurement>();
  qRegisterMetaType<armmimic::AnalysisSummary>();
  qRegisterMetaType<armmimic::StandstillJoints>();
  worker_->moveToThread(&thread_);
  connect(&thread_, &QThread::finished, worker_, &QObject::deleteLater);
  connect(worker_, &AnalysisWorker::phase, this, &AnalysisJob::phase);
  connect(worker_, &AnalysisWorker::progress, this, &AnalysisJob::progress);
  connect(worker_, &AnalysisWorker::estimated, this, &AnalysisJob::estimated);
  connect(worker_, &AnalysisWorker::measured, this, &AnalysisJob::measured);
  connect(worker_, &AnalysisWorker::liveFrame, this, &AnalysisJob::liveFrame);
  connect(worker_, &AnalysisWorker::analysisFinished, this,
          [this](const QString& error, const QString& key, const AnalysisSummary& summary) {
            running_ = false;
            if (!error.isEmpty()) {
              // The last result stays: a failed run replaces nothing.
              emit failed(error, key);
              emit finished(false, false);
              return;
            }
            result_options_ = pending_options_;
            result_paths_.clear();
            for (const std::string& path :
                 ArmOutputPaths(result_options_, pending_path_.toStdString())) {
              result_paths_ << QString::fromStdString(path);
            }
            summary_ = summary;
            emit finished(true, summary.cancelled);
          });
  connect(worker_, &AnalysisWorker::backgroundFinished, this,
          [this](const QString& error, const QString& path) {
            running_ = false;
            if (!error.isEmpty()) {
              emit failed(error);
              emit finished(false, cancel_.load());
              return;
            }
            emit backgroundReady(path);
            emit finished(true, false);
          });
  connect(worker_, &AnalysisWorker::standstillFinished, this,
          [this](const QString& error, const QString& key, const StandstillJoints& joints) {
            running_ = false;
            if (!error.isEmpty()) {
              emit failed(error, key);
              emit finished(false, false);
              return;
            }
            const bool cancelled = cancel_.load();
            if (!cancelled) emit standstillReady(joints);
            emit finished(true, cancelled);
          });
  thread_.setObjectName("armmimic-analysis");
  thread_.start();
}

AnalysisJob::~AnalysisJob() {
  cancel_.store(true);
  thread_.quit();
  thread_.wait();
}

QString AnalysisJob::exportResult(const QString& path) const {
  if (result_paths_.isEmpty()) return tr("Nothing to export yet: run the analysis first (F5)");
  const std::vector<std::string> targets = ArmOutputPaths(result_options_, path.toStdString());
  if (targets.size() != static_cast<std::size_t>(result_paths_.size())) {
    return tr("%1: the result has %2 angle files").arg(path).arg(result_paths_.size());
  }
  for (int i = 0; i < result_paths_.size(); ++i) {
    QFile in(result_paths_[i]);
    if (!in.open(QIODevice::ReadOnly)) {
      return tr("%1: cannot read the analysis result: %2").arg(result_paths_[i], in.errorString());
    }
    const QByteArray bytes = in.readAll();
    const Status st = WriteOutputFile(targets[static_cast<std::size_t>(i)], bytes.toStdString());
    if (!st) return QString::fromStdString(st.message());
  }
  return QString();
}

void AnalysisJob::adoptResult(const QString& path) {
  if (running_) return;
  result_paths_ = QStringList{path};
  result_options_ = AnalysisOptions();  // one file, exported as it is
  summary_ = AnalysisSummary();
}

QString AnalysisJob::adoptResultTexts(const QStringList& texts, const AnalysisOptions& options) {
  if (running_) return tr("An analysis is running");
  if (!session_.isValid()) {
    return tr("cannot create a temporary folder for the results: %1").arg(session_.errorString());
  }
  const QString path = QDir(session_.path()).filePath(QString("angles-%1.tsv").arg(++run_));
  const std::vector<std::string> paths = ArmOutputPaths(options, path.toStdString());
  if (paths.size() != static_cast<std::size_t>(texts.size())) {
    return tr("the results hold %1 angle files, the settings %2")
        .arg(texts.size())
        .arg(paths.size());
  }
  QStringList written;
  for (std::size_t i = 0; i < paths.size(); ++i) {
    const Status st = WriteOutputFile(paths[i], texts[static_cast<int>(i)].toStdString());
    if (!st) return QString::fromStdString(st.message());
    written << QString::fromStdString(paths[i]);
  }
  result_paths_ = written;
  result_options_ = options;
  summary_ = AnalysisSummary();
  return QString();
}

QString AnalysisJob::describeResult(bool cancelled) const {
  const QString done = cancelled ? tr("cancelled") : tr("done");
  // Where the lost rows went: the most frequent reasons, as the CLI's report names them.
  const QString why =
      summary_.lost > 0
          ? tr("; lost rows: %1")
                .arg(QString::fromStdString(summary_.lost_reasons.Text(LostReasons::kReported)))
          : QString();
  if (summary_.arms.size() == 2) {
    const AnalysisSummary::ArmRows &left = summary_.arms[0], &right = summary_.arms[1];
    return tr("Analysis %1: %2 rows per arm, left %3 ok, %4 lost, right %5 ok, %6 lost in %7 s")
               .arg(done)
               .arg(left.frames)
               .arg(left.ok)
               .arg(left.lost)
               .arg(right.ok)
               .arg(right.lost)
               .arg(summary_.seconds, 0, 'f', 2) +
           why;
  }
  return tr("Analysis %1: %2 rows, %3 ok, %4 lost in %5 s")
             .arg(done)
             .arg(summary_.frames)
             .arg(summary_.ok)
             .arg(summary_.lost)
             .arg(summary_.seconds, 0, 'f', 2) +
         why;
}

bool AnalysisJob::start(const AnalysisOptions& options, bool live) {
  if (running_) return false;
  const Status st = options.Check();
  if (!st) {
    emit failed(QString::fromStdString(st.message()), QString::fromStdString(st.key()));
    return false;
  }
  if (!session_.isValid()) {
    emit failed(
        tr("cannot create a temporary folder for the results: %1").arg(session_.errorString()));
    return false;
  }
  cancel_.store(false);
  running_ = true;
  pending_path_ = QDir(session_.path()).filePath(QString("angles-%1.tsv").arg(++run_));
  pending_options_ = options;
  emit started();
  QMetaObject::invokeMethod(worker_, [w = worker_, options, path = pending_path_, live] {
    w->analyze(options, path, live);
  });
  return true;
}

bool AnalysisJob::startBackground(const QStringList& inputs, int start, int count,
                                  const QString& path) {
  if (running_) return false;
  cancel_.store(false);
  running_ = true;
  emit started();
  QMetaObject::invokeMethod(worker_, [w = worker_, inputs, start, count, path] {
    w->estimateBackground(inputs, start, count, path);
  });
  return true;
}

bool AnalysisJob::startStandstill(const AnalysisOptions& options) {
  if (running_) return false;
  cancel_.store(false);
  running_ = true;
  emit started();
  QMetaObject::invokeMethod(worker_, [w = worker_, options] { w->estimateStandstill(options); });
  return true;
}

void AnalysisJob::cancel() { cancel_.store(true); }

bool AnalysisJob::waitForFinished(int timeout_ms) {
  QElapsedTimer t;
  t.start();
  while (running_ && t.elapsed() < timeout_ms) {
    QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
    QThread::msleep(2);
  }
  QCoreApplication::processEvents();
  return !running_;
}

}  // namespace armmimic::gui
