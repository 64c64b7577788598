// StatusLine: the status bar's contents: frame and time, the analysis phase and progress, and
// the robot link state.
#pragma once

#include <QObject>
#include <QString>

class QLabel;
class QProgressBar;
class QStatusBar;

namespace armmimic::gui {

class StatusLine : public QObject {
  Q_OBJECT
 public:
  explicit StatusLine(QStatusBar* bar);

  void setFrameText(const QString& text);
  // "frame 12 / 99   0.40 s   ok"; with no video, "No video".
  // `time_s` NaN (still images) shows no time.
  void showFrame(const QString& frame, double time_s, const QString& state);
  void showNoVideo();
  QString frameText() const;
  QString linkText() const;

 public slots:
  void setBusy(bool busy);
  void setPhase(const QString& phase);
  void setProgress(int done, int total);
  void setLinkText(const QString& text);

 private:
  QLabel* frame_;
  QLabel* phase_;
  QProgressBar* progress_;
  QLabel* link_;
};

}  // namespace armmimic::gui
