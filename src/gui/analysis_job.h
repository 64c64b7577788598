// AnalysisJob: runs armmimic::AnalyzeToFile (the same call as `armmimic-cli analyze`),
// EstimateBackground or EstimateStandstillJoints on a worker thread. Cancel is an atomic flag;
// progress, measurements and the end are signals. The angle file goes to a session folder;
// exporting copies it, so the GUI's export is byte-for-byte what the CLI writes for the same
// options.
#pragma once

#include <atomic>

#include <QImage>
#include <QObject>
#include <QString>
#include <QTemporaryDir>
#include <QThread>

#include "armmimic/engines/analysis.h"
#include "armmimic/engines/standstill_estimate.h"

namespace armmimic::gui {

class AnalysisWorker : public QObject {
  Q_OBJECT
 public:
  explicit AnalysisWorker(std::atomic<bool>* cancel) : cancel_(cancel) {}

 public slots:
  void analyze(const armmimic::AnalysisOptions& options, const QString& output_path, bool live);
  void estimateBackground(const QStringList& inputs, int start, int count,
                          const QString& output_path);
  void estimateStandstill(const armmimic::AnalysisOptions& options);

 signals:
  void phase(const QString& text);
  void progress(int done, int total);
  // A value the engine estimated or a choice it made, told once (AnalysisCallbacks::on_estimate).
  void estimated(const QString& text);
  void measured(const armmimic::ArmMeasurement& m);
  void liveFrame(int index, const QImage& image, double time_s);
  // `error_key`: the setting the error is about (Status::key()), or "".
  void analysisFinished(const QString& error, const QString& error_key,
                        const armmimic::AnalysisSummary& summary);
  void backgroundFinished(const QString& error, const QString& output_path);
  void standstillFinished(const QString& error, const QString& error_key,
                          const armmimic::StandstillJoints& joints);

 private:
  std::atomic<bool>* cancel_;
};

class AnalysisJob : public QObject {
  Q_OBJECT
 public:
  explicit AnalysisJob(QObject* parent = nullptr);
  ~AnalysisJob() override;

  bool isRunning() const { return running_; }
  // Starts an analysis; returns false (and emits failed) when the options do not check out.
  bool start(const AnalysisOptions& options, bool live = false);
  bool startBackground(const QStringList& inputs, int start, int count, const QString& path);
  // The joints the lk or hybrid run of `options` calibrates itself from (standstillReady, or
  // failed with the setting's key).
  bool startStandstill(const AnalysisOptions& options);
  void cancel();
  // The angle file of the last finished analysis ("" when none); with both arms analysed (the
  // pose engine's side both), the left arm's.
  QString resultPath() const { return result_paths_.value(0); }
  // Every angle file of the last finished analysis: one, or the left and the right arm's.
  const QStringList& resultPaths() const { return result_paths_; }
  // The folder the results live in until exported (removed with this job).
  QString resultFolder() const { return session_.path(); }
  // Copies the last result to `path` (atomically: a failed export leaves no half file); with
  // both arms, to the arm files of `path` (A.left.tsv and A.right.tsv for A.tsv, ArmOutputPaths).
  // Returns "" or what went wrong, naming the file.
  QString exportResult(const QString& path) const;
  // "Analysis done: 40 rows, 38 ok, 2 lost in 0.25 s; lost rows: no arm (2)"
  QString describeResult(bool cancelled) const;
  // Takes an angle file made elsewhere (File > Open angle file) as the result: export copies it.
  void adoptResult(const QString& path);
  // Takes angle file texts (a session's results: one, or with both arms the left and the right
  // arm's) as the result of a run with `options`, kept in the session folder. Returns "" or what
  // went wrong.
  QString adoptResultTexts(const QStringList& texts, const AnalysisOptions& options);
  // Forgets the last result (another input was opened): nothing to export until the next run.
  void forgetResult() {
    if (!running_) result_paths_.clear();
  }
  const AnalysisSummary& summary() const { return summary_; }
  bool waitForFinished(int timeout_ms);  // for tests and shutdown; pumps events

 signals:
  void started();
  void phase(const QString& text);
  void progress(int done, int total);
  void estimated(const QString& text);
  void measured(const armmimic::ArmMeasurement& m);
  void liveFrame(int index, const QImage& image, double time_s);
  void finished(bool ok, bool cancelled);
  void backgroundReady(const QString& path);
  void standstillReady(const armmimic::StandstillJoints& joints);
  // `key`: the setting the message is about (Status::key()), or "" (EngineSettingsPanel::showError
  // words it for the panel).
  void failed(const QString& message, const QString& key = QString());

 private:
  QThread thread_;
  AnalysisWorker* worker_;
  std::atomic<bool> cancel_{false};
  QTemporaryDir session_;
  bool running_ = false;
  int run_ = 0;
  AnalysisOptions pending_options_;  // of the run going on, then of the result
  QString pending_path_;
  QStringList result_paths_;
  AnalysisOptions result_options_;
  AnalysisSummary summary_;
};

}  // namespace armmimic::gui

Q_DECLARE_METATYPE(armmimic::AnalysisOptions)
Q_DECLARE_METATYPE(armmimic::ArmMeasurement)
Q_DECLARE_METATYPE(armmimic::AnalysisSummary)
Q_DECLARE_METATYPE(armmimic::StandstillJoints)
