// PlaybackBar: transport buttons (bound to the window's actions), the scrub slider, the frame and
// time readout and the speed choice.
#pragma once

#include <QWidget>

class QAction;
class QComboBox;
class QLabel;
class QSettings;
class QSlider;

namespace armmimic::gui {

class PlaybackBar : public QWidget {
  Q_OBJECT
 public:
  explicit PlaybackBar(QWidget* parent = nullptr);

  // Buttons for these actions, in order, left of the slider.
  void addActions(const QList<QAction*>& actions);
  void setFrameCount(int count, double fps);
  void setPosition(int frame, double time_s);
  int position() const;
  double speed() const;
  void setSpeed(double speed);
  void saveSettings(QSettings& settings) const;
  void loadSettings(QSettings& settings);

 signals:
  void seekRequested(int frame);
  void speedChanged(double speed);

 private:
  QWidget* buttons_;
  QSlider* slider_;
  QLabel* label_;
  QComboBox* speed_;
  int count_ = 0;
  double fps_ = 0;
};

}  // namespace armmimic::gui
